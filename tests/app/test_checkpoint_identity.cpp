// A checkpoint's identity (app/checkpoint_file.h): the thread count enters it only where it
// changes a run's bits.

#include <gtest/gtest.h>

#include <omp.h>

#include "app/checkpoint_file.h"
#include "core/scene/scene.h"

namespace sedem::app {
namespace {

// The identity of `scene` when `threads` is every core there is (integrator.threads = 0).
std::string identity_on(Scene scene, int threads) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  const std::string id = run_identity(scene);
  omp_set_num_threads(before);
  return id;
}

TEST(CheckpointIdentity, TheThreadCountCountsOnlyWhereItChangesTheBits) {
  Scene local;  // the default: exponential, local steps, every core
  ASSERT_EQ(local.integrator.threads, 0);
  EXPECT_EQ(identity_on(local, 1), identity_on(local, 2));

  Scene global = local;
  global.integrator.local_steps = false;
  EXPECT_NE(identity_on(global, 1), identity_on(global, 2));

  // Lubrication needs the force pass: local_steps = true then steps every grain together.
  Scene lubricated = local;
  lubricated.forces.lubrication = true;
  EXPECT_NE(identity_on(lubricated, 1), identity_on(lubricated, 2));

  Scene seeded = local;
  seeded.sample.seed += 1;
  EXPECT_NE(identity_on(seeded, 1), identity_on(local, 1));
}

}  // namespace
}  // namespace sedem::app
