#include <gtest/gtest.h>

#include <cstdint>

#include "core/engine/forces/drag_evaluator.h"
#include "core/engine/forces/force_model.h"
#include "core/engine/forces/voidage_grid.h"

namespace sedem {
namespace {

// A crowded column of 1 mm cells, a grain of 20 um standing for many real ones.
struct Column {
  ForceModel model;
  VoidageGrid voidage;
  DragEvaluator drag;
  Column() {
    voidage.configure(1e-3, 0.005, 0.02, 1e-3, 0.4, 1);
    for (std::size_t c = 0; c < voidage.cell_count(); ++c) voidage.deposit(c, 2e-11 + 1e-13 * c);
    drag = {&model, &voidage, di_felice_tail_re(voidage.min_voidage())};
  }
};

constexpr double kD = 20e-6, kWeight = 4e3, kSpeed = 2e-4;

// The memo gives the same bits as evaluating anew while the grain's cell holds the same solids,
// and evaluates anew once they change, once the grain moves to another cell, or once the memo
// is another grain's (the state is re-sorted under it).
TEST(DragMemo, SameBitsAsEvaluatingAnewAndAnewWhereTheCellChanged) {
  Column col;
  DragEvaluator& drag = col.drag;
  const double x = 0.0012, y = 0.0073;
  DragMemo memo;
  const double plain = drag.coefficient(kD, kWeight, kSpeed, x, y);
  EXPECT_EQ(drag.coefficient(kD, kWeight, kSpeed, x, y, &memo, 7), plain);
  EXPECT_EQ(memo.grain, 7u);
  EXPECT_EQ(memo.cell, col.voidage.cell(x, y));
  // Read back, at another speed too (the speed is not in the memo).
  EXPECT_EQ(drag.coefficient(kD, kWeight, kSpeed, x, y, &memo, 7), plain);
  EXPECT_EQ(drag.coefficient(kD, kWeight, 3 * kSpeed, x, y, &memo, 7),
            drag.coefficient(kD, kWeight, 3 * kSpeed, x, y));

  // Another grain joins the cell: its solids change, so does the drag.
  col.voidage.deposit(col.voidage.cell(x, y), 5e-12);
  const double crowded = drag.coefficient(kD, kWeight, kSpeed, x, y);
  ASSERT_NE(crowded, plain);
  EXPECT_EQ(drag.coefficient(kD, kWeight, kSpeed, x, y, &memo, 7), crowded);

  // The grain moves to a cell of other solids.
  const double below = drag.coefficient(kD, kWeight, kSpeed, x, y - 0.003);
  ASSERT_NE(below, crowded);
  EXPECT_EQ(drag.coefficient(kD, kWeight, kSpeed, x, y - 0.003, &memo, 7), below);

  // Grain 8, twice as coarse, in grain 7's place with grain 7's memo: its own drag.
  const double coarse = drag.coefficient(2 * kD, kWeight, kSpeed, x, y - 0.003);
  EXPECT_EQ(drag.coefficient(2 * kD, kWeight, kSpeed, x, y - 0.003, &memo, 8), coarse);
  EXPECT_EQ(memo.grain, 8u);
}

}  // namespace
}  // namespace sedem
