// mb2_defaults.hpp — Mandelbulber2 2.20's default value of every key the importer reads. A
// `.fract` file lists "only modified parameters", so every absent key takes these (not the
// values Fractalis's own scenes start from: Mandelbulber2's bulb has power 9 and N is 250).
// Values are written as Mandelbulber2 writes them, so they go through the same readers
// (fract_values.hpp) as the file's own values. Taken from Mandelbulber2 2.20's parameter
// initialisation (its source, as facts: no code of it is here).
#pragma once

#include "import/fract_file.hpp"

#include <span>
#include <string>

namespace fr {

struct Mb2Default {
  const char* key;
  const char* value;
};

// [main_parameters] keys, then the keys every [fractal_N] section has (the same in each slot).
std::span<const Mb2Default> mb2_main_defaults();
std::span<const Mb2Default> mb2_fractal_defaults();

// The entry for `key`: the file's, else the default (line 0). Throws a FractError for a key that
// has no default here (a programming error: the importer reads only keys in the tables).
FractEntry mb2_main_entry(const FractFile& f, const std::string& key);
FractEntry mb2_fractal_entry(const FractFile& f, int slot, const std::string& key);

}  // namespace fr
