#include "app/qt_platform.h"

#include <QByteArray>
#include <QtGlobal>

namespace sedem::app {

void use_offscreen_platform() {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
    qputenv("QT_QPA_PLATFORM", QByteArray("offscreen"));
}

}  // namespace sedem::app
