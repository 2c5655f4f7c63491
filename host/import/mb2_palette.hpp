// mb2_palette.hpp — Mandelbulber2's surface colour gradient (mat1_surface_color_gradient), read
// and evaluated as Mandelbulber2 2.20 does, for the importer's palette colouring.
//
// The gradient is written as `pos RRGGBB` pairs (pos 0..10000, 8-bit hex colours); files from
// before 2.19 have a palette instead (mat1_surface_color_palette: colours alone, evenly spaced),
// which Mandelbulber2 turns into a gradient on load. Either way the first colour is repeated at
// position 1 (the gradient wraps), and a colour at a position is interpolated linearly between
// the stops around it. (Its rules as facts; the code is written here.)
#pragma once

#include "import/fract_file.hpp"

#include <array>
#include <string>
#include <vector>

namespace fr {

struct Mb2GradientStop {
  float position = 0;        // 0..1 (as Mandelbulber2 keeps it, in float)
  std::array<int, 3> rgb{};  // 0..255
};

struct Mb2Gradient {
  std::vector<Mb2GradientStop> stops;  // sorted by position, the wrap stop included
  int colours = 0;                     // stops in the file (without the wrap stop)
};

// A gradient string (`pos RRGGBB ...`). A token that is not a position or a hex colour (1-6
// digits), or no colour at all, is a FractError naming the file, line and key.
Mb2Gradient mb2_parse_gradient(const FractFile& f, const std::string& key, const FractEntry& e);

// A pre-2.19 palette (`RRGGBB RRGGBB ...`): colour i of n at position int(i / n * 10000).
Mb2Gradient mb2_parse_old_palette(const FractFile& f, const std::string& key, const FractEntry& e);

// The gradient's colour at `position` (0..1), each channel 0..1 (display values, sRGB).
std::array<double, 3> mb2_gradient_colour(const Mb2Gradient& g, float position);

// An sRGB display value (0..1) as a linear one.
double srgb_to_linear(double c);

}  // namespace fr
