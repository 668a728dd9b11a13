#include "core/engine/engine_config.h"

namespace sedem {

IntegratorMethod integrator_method(const IntegratorConfig& c) {
  return c.method == "explicit" || c.method == kFormerExplicitName
             ? IntegratorMethod::explicit_euler
             : IntegratorMethod::exponential;
}

}  // namespace sedem
