#include "core/engine/integrate/integrator.h"

namespace sedem {

std::unique_ptr<Integrator> make_integrator(const IntegratorConfig& config,
                                            const IntegratorContext& context) {
  if (config.method == "reference") return make_reference_integrator(config, context);
  return make_exponential_integrator(config, context);
}

}  // namespace sedem
