#pragma once

#include "core/model/cylinder.h"
#include "core/model/particles.h"

namespace sedem {

// Renumbers the particles of each size class along a Z-order curve of their positions
// (cells of the mean spacing), the classes by their index (build_sample deals them out in
// that order, so they keep it); ids become the new indices. Same positions, same order: a
// run is as reproducible as before.
//
// Why: the local stepper keeps each grain's state by its index. Grains of one size coast on
// windows of one length and come up for their syncs together, in index order, so a class's
// indices in a row keep that stream sequential in memory; and along the curve the neighbours a
// sync looks up (boxes, windows) lie near the grain's own (docs/results/engine.md, "Grains
// numbered along a curve").
void order_for_memory(Particles& particles, const Cylinder& cylinder);

}  // namespace sedem
