// fract_values.hpp — the values of a `.fract` file's entries, read as Mandelbulber2 writes them:
// numbers with either decimal separator ("1,5" or "1.5", as the saving machine's locale had it),
// vectors as three numbers, colours as three 16-bit hex words ("ff00 9700 0"), booleans as
// true/false, integers. A value that is not of the asked type, or not finite, is a FractError
// naming the file, line and key.
#pragma once

#include "import/fract_file.hpp"

#include <array>
#include <string>

namespace fr {

double fract_number(const FractFile& f, const std::string& key, const FractEntry& e);
long long fract_integer(const FractFile& f, const std::string& key, const FractEntry& e);
bool fract_bool(const FractFile& f, const std::string& key, const FractEntry& e);
std::array<double, 3> fract_vec3(const FractFile& f, const std::string& key, const FractEntry& e);
// A colour as three components in [0, 1] (each 16-bit word over 65535).
std::array<double, 3> fract_colour(const FractFile& f, const std::string& key, const FractEntry& e);

}  // namespace fr
