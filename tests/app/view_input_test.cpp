// The viewer's cursor in framebuffer pixels: a click on a HiDPI display picks
// the pixel under the cursor, not the one at half its coordinates.
#include <gtest/gtest.h>

#include "view/input_event.hpp"

namespace sg::app::view {
namespace {

TEST(ViewInput, TheCursorIsScaledToTheFramebuffersPixels) {
  const CursorPosition same = framebufferPixel(160.0, 90.0, 320, 180, 320, 180);
  EXPECT_EQ(same.x, 160.0);
  EXPECT_EQ(same.y, 90.0);
  const CursorPosition hidpi = framebufferPixel(160.0, 90.0, 320, 180, 640, 360);  // a 2x display
  EXPECT_EQ(hidpi.x, 320.0);
  EXPECT_EQ(hidpi.y, 180.0);
  const CursorPosition scaled = framebufferPixel(100.0, 40.0, 800, 600, 1200, 900);  // 150% desktop scaling
  EXPECT_EQ(scaled.x, 150.0);
  EXPECT_EQ(scaled.y, 60.0);
  const CursorPosition minimized = framebufferPixel(5.0, 7.0, 0, 0, 0, 0);
  EXPECT_EQ(minimized.x, 5.0);
  EXPECT_EQ(minimized.y, 7.0);
}

}  // namespace
}  // namespace sg::app::view
