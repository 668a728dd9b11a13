#include "app/qt_platform.h"

#include <sys/stat.h>
#include <unistd.h>

#include <QByteArray>
#include <QtGlobal>

#include <string>

namespace sedem::app {

void use_offscreen_platform() {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
    qputenv("QT_QPA_PLATFORM", QByteArray("offscreen"));
  // Qt wants a private runtime folder and warns on every start without one (root shells and
  // CI have none). Give it one, as Qt itself would, but quietly.
  if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
    const std::string dir = "/tmp/sedem-runtime-" + std::to_string(getuid());
    ::mkdir(dir.c_str(), 0700);
    qputenv("XDG_RUNTIME_DIR", QByteArray(dir.c_str()));
  }
}

}  // namespace sedem::app
