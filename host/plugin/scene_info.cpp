#include "plugin/scene_info.hpp"

namespace fr {

const char* param_type_name(fr_param_type type) {
  switch (type) {
    case FR_PARAM_FLOAT:
      return "float";
    case FR_PARAM_INT:
      return "int";
    case FR_PARAM_BOOL:
      return "bool";
    case FR_PARAM_VEC3:
      return "vec3";
    case FR_PARAM_COLOR:
      return "color";
  }
  return "unknown";
}

int SceneInfo::find_param(const std::string& key) const {
  for (size_t i = 0; i < params.size(); ++i)
    if (params[i].key == key) return static_cast<int>(i);
  return -1;
}

}  // namespace fr
