#pragma once

#include "core/model/cylinder.h"
#include "core/sample/sample_config.h"

namespace sedem {

// What the sample stage needs: the soil and the section it is placed in.
struct SampleSetup {
  SampleConfig sample;
  Cylinder cylinder;
};

}  // namespace sedem
