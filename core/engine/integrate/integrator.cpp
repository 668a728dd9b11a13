#include "core/engine/integrate/integrator.h"

namespace sedem {

std::unique_ptr<Integrator> make_integrator(const IntegratorConfig& config,
                                            const IntegratorContext& context) {
  if (integrator_method(config) == IntegratorMethod::explicit_euler)
    return make_explicit_integrator(config, context);
  return make_exponential_integrator(config, context);
}

}  // namespace sedem
