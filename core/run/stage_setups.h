#pragma once

// The one place a Scene is taken apart: each stage gets the setup it needs and nothing more.

#include "core/engine/engine_setup.h"
#include "core/instruments/test_setup.h"
#include "core/sample/sample_setup.h"
#include "core/scene/scene.h"

namespace sedem {

EngineSetup engine_setup(const Scene& scene);
SampleSetup sample_setup(const Scene& scene);
TestSetup test_setup(const Scene& scene);

}  // namespace sedem
