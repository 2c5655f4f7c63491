#include "app/scene_slot.hpp"

namespace fr {

std::vector<fr_value> rebind_params(const SceneInfo& old_info,
                                    const std::vector<fr_value>& old_values,
                                    const SceneInfo& new_info) {
  std::vector<fr_value> values;
  for (const ParamInfo& p : new_info.params) {
    const int old_index = old_info.find_param(p.key);
    const bool same_kind =
        old_index >= 0 && old_info.params[old_index].component_count() == p.component_count();
    values.push_back(same_kind ? old_values[old_index] : p.default_value);
  }
  clamp_params(new_info, values);
  return values;
}

}  // namespace fr
