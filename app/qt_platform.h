#pragma once

namespace sedem::app {

// sedem never opens a window: Qt runs on its offscreen platform unless the user chose
// another with QT_QPA_PLATFORM.
void use_offscreen_platform();

}  // namespace sedem::app
