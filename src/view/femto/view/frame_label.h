#pragma once
// A time stamp burned into a displayed frame ("OPL 3.125"), so a GIF or a
// folder of PNGs says when each frame is without a separate legend. A tiny
// built-in 5x7 pixel font: no font library for a dozen characters.
#include <string>

#include <femto/image/image_io.h>
#include <femto/time/time_grid.h>

namespace femto {

/// The label of bin `bin`: its centre as "OPL x" with enough decimals to tell
/// neighbouring bins apart.
std::string binLabel(const TimeGrid& grid, int bin);

/// Draw `text` (digits, space, . + - = and the letters of "OPL bin") in white
/// on a black box at the top-left of a display image (values in [0, 1]), at
/// an integer scale that grows with the image (7 pixels tall below 128 rows).
/// Other characters draw as blanks; text wider than the image is clipped.
void drawLabel(Bitmap& image, const std::string& text);

}  // namespace femto
