#pragma once

// Each stage's keys in a scene file: name, unit, range and help, bound to the stage's config.
// They live with the scene, which reads them, so that no stage knows of files or schemas.

#include "core/engine/engine_config.h"
#include "core/instruments/instruments_config.h"
#include "core/sample/sample_config.h"
#include "core/scene/schema.h"

namespace sedem {

void describe(SampleConfig& config, Schema& schema);
void describe(InstrumentsConfig& config, Schema& schema);
void describe(ForcesConfig& config, Schema& schema);
void describe(IntegratorConfig& config, Schema& schema);

}  // namespace sedem
