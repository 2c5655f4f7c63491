// environment_map.hpp — an HDR panorama as the render kernel reads it (kernels/environment.cl):
// its pixels, then the distributions that sample it in proportion to the light it sends.
#pragma once

#include "io/environment_image.hpp"

#include <vector>

namespace fr {

// The buffer environment.cl reads: the RGB pixels (3 floats each, rows top to bottom); then, over
// the bilinear patches between pixel centres (width x (height + 1): columns wrap, and the first
// and last rows are half patches up to the poles, where rows clamp), the patch rows' cumulative
// distribution (height + 2 floats from 0 to 1) and each patch row's over its patches ((height + 1)
// x (width + 1) floats from 0 to 1). A patch's weight is its mean luminance (of its four corner
// pixels) times the sine of its centre's polar angle times its area: the light it sends. Within
// a patch the kernel samples the bilinear luminance itself, so the density follows the lookup.
// A black panorama is sampled by solid angle alone.
std::vector<float> environment_buffer(const EnvironmentImage& image);

}  // namespace fr
