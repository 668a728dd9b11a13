#include "core/engine/instability.h"

#include <sstream>
#include <utility>

namespace sedem {

InstabilityError::InstabilityError(std::uint32_t id, double t, std::string what, double v)
    : std::runtime_error([&] {
        std::ostringstream m;
        m << "instability: particle " << id << " at t = " << t << " s: " << what << " = " << v;
        return m.str();
      }()),
      particle_id(id),
      time(t),
      quantity(std::move(what)),
      value(v) {}

}  // namespace sedem
