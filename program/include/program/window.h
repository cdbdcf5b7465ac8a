// --window: the chapter's figures in a window (SDL2), one at a time, each drawn by the
// chapter's own code when it is shown, as the book's interactive demos show theirs.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "program/figure.h"

namespace cgfs {

// What the window does with the keys, as H or F1 prints it.
inline constexpr char kWindowKeys[] =
    "keys: Left / Right the previous / next figure, C its cost view and back (where it has "
    "one), S save it, R back to the chapter's view, H or F1 these keys, Esc quit; where the "
    "figure has a camera: Up / Down forward / back, "
    "A / D left / right, PageUp / PageDown up / down, Q / E or dragging the mouse turn "
    "left / right, Home / End or dragging the mouse look up / down";

// The keys move the camera as program/camera_controls.h says.
// Shows the figures at width x height in a window titled with the chapter, the figure,
// the last drawing's time and, once moved, the view. A figure with a camera starts from
// `view` and moves with the keys, each step drawn by the chapter's code. S writes the
// figure shown into `output` (created then) as <name>.<format> and prints its path and
// the view that draws it again (--view). Returns when the window is closed or Esc is
// pressed. Throws cgfs::Error with one line when there is no display to open it on, or
// when this build has no SDL2.
void ShowFigures(const std::string& chapter, const std::vector<const Figure*>& figures, int width,
                 int height, const std::filesystem::path& output, const std::string& format,
                 const View& view = {});

}  // namespace cgfs
