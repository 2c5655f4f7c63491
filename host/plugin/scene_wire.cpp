#include "plugin/scene_wire.hpp"

#include "plugin/scene_checks.hpp"

#include <cstring>

namespace fr {

void WireWriter::str(std::string_view s) {
  u32(static_cast<uint32_t>(s.size()));
  raw(s.data(), s.size());
}

bool WireReader::take(void* out, size_t n) {
  if (n == 0) return !failed_;  // `out` may be null then (an empty vector's data())
  if (failed_ || bytes_.size() - at_ < n) {
    failed_ = true;
    std::memset(out, 0, n);
    return false;
  }
  std::memcpy(out, bytes_.data() + at_, n);
  at_ += n;
  return true;
}

std::string WireReader::str(size_t cap) {
  const uint32_t n = u32();
  if (failed_ || n > cap || bytes_.size() - at_ < n) {
    failed_ = true;
    return {};
  }
  std::string s(bytes_.substr(at_, n));
  at_ += n;
  return s;
}

namespace {

void write_value(WireWriter& w, const fr_value& v) {
  for (double c : v.v) w.f64(c);
}
fr_value read_value(WireReader& r) {
  fr_value v{};
  for (double& c : v.v) c = r.f64();
  return v;
}

void write_camera(WireWriter& w, const fr_camera& c) {
  for (double x : c.eye) w.f64(x);
  for (double x : c.target) w.f64(x);
  for (double x : c.up) w.f64(x);
  w.f64(c.fov_deg);
}
fr_camera read_camera(WireReader& r) {
  fr_camera c{};
  c.struct_size = sizeof c;
  for (double& x : c.eye) x = r.f64();
  for (double& x : c.target) x = r.f64();
  for (double& x : c.up) x = r.f64();
  c.fov_deg = r.f64();
  return c;
}

void write_light(WireWriter& w, const fr_light& l) {
  w.u32(l.kind);
  for (double x : l.vector) w.f64(x);
  for (double x : l.color) w.f64(x);
  w.f64(l.intensity);
  w.f64(l.attenuation);
  w.f64(l.falloff);
  w.f64(l.radius);
}
fr_light read_light(WireReader& r) {
  fr_light l{};
  l.struct_size = sizeof l;
  l.kind = r.u32();
  for (double& x : l.vector) x = r.f64();
  for (double& x : l.color) x = r.f64();
  l.intensity = r.f64();
  l.attenuation = r.f64();
  l.falloff = r.f64();
  l.radius = r.f64();
  return l;
}

}  // namespace

void write_scene_info(WireWriter& w, const SceneInfo& info) {
  for (const std::string* s :
       {&info.id, &info.name, &info.version, &info.author, &info.license, &info.description,
        &info.tags, &info.credit, &info.de_source, &info.de_source_name, &info.surface_source,
        &info.surface_source_name})
    w.str(*s);
  w.u32(static_cast<uint32_t>(info.params.size()));
  for (const ParamInfo& p : info.params) {
    for (const std::string* s : {&p.key, &p.name, &p.group, &p.description}) w.str(*s);
    w.u32(p.type);
    w.u32(p.flags);
    write_value(w, p.default_value);
    write_value(w, p.min_value);
    write_value(w, p.max_value);
    w.u32(static_cast<uint32_t>(p.choices.size()));
    for (const std::string& c : p.choices) w.str(c);
    w.f64(p.detail_ratio);
  }
  w.u64(info.features);
  write_camera(w, info.camera);
  w.u32(static_cast<uint32_t>(info.lights.size()));
  for (const fr_light& l : info.lights) write_light(w, l);
  w.f64(info.bounding_radius);
}

bool read_scene_info(WireReader& r, SceneInfo* info) {
  SceneInfo s;
  s.id = r.str(kMaxIdBytes);
  s.name = r.str(kMaxLabelBytes);
  s.version = r.str(kMaxLabelBytes);
  s.author = r.str(kMaxLabelBytes);
  s.license = r.str(kMaxLabelBytes);
  s.description = r.str(kMaxDescriptionBytes);
  s.tags = r.str(kMaxLabelBytes);
  s.credit = r.str(kMaxLabelBytes);
  s.de_source = r.str(kMaxSourceBytes);
  s.de_source_name = r.str(kMaxLabelBytes);
  s.surface_source = r.str(kMaxSourceBytes);
  s.surface_source_name = r.str(kMaxLabelBytes);
  const uint32_t param_count = r.u32();
  if (r.failed() || param_count > kMaxSceneParams) return false;
  for (uint32_t i = 0; i < param_count; ++i) {
    ParamInfo p;
    p.key = r.str(kMaxIdBytes);
    p.name = r.str(kMaxLabelBytes);
    p.group = r.str(kMaxLabelBytes);
    p.description = r.str(kMaxDescriptionBytes);
    p.type = r.u32();
    p.flags = r.u32();
    p.default_value = read_value(r);
    p.min_value = read_value(r);
    p.max_value = read_value(r);
    const uint32_t choice_count = r.u32();
    if (r.failed() || choice_count > kMaxChoices) return false;
    for (uint32_t c = 0; c < choice_count; ++c) p.choices.push_back(r.str(kMaxIdBytes));
    p.detail_ratio = r.f64();
    s.params.push_back(std::move(p));
  }
  s.features = r.u64();
  s.camera = read_camera(r);
  const uint32_t light_count = r.u32();
  if (r.failed() || light_count > FR_MAX_SCENE_LIGHTS) return false;
  for (uint32_t i = 0; i < light_count; ++i) s.lights.push_back(read_light(r));
  s.bounding_radius = r.f64();
  if (r.failed()) return false;
  *info = std::move(s);
  return true;
}

void write_scene_state(WireWriter& w, const SceneState& state) {
  w.f64(state.time_s);
  w.f64(state.dt_s);
  w.u64(state.frame_index);
  w.f64(state.bounding_radius);
  write_camera(w, state.camera);
  for (double x : state.camera_lo.eye) w.f64(x);
  for (double x : state.camera_lo.target) w.f64(x);
  w.u32(static_cast<uint32_t>(state.params.size()));
  for (const fr_value& v : state.params) write_value(w, v);
  w.u32(static_cast<uint32_t>(state.lights.size()));
  for (const fr_light& l : state.lights) write_light(w, l);
}

bool read_scene_state(WireReader& r, size_t param_count, size_t light_count, SceneState* state) {
  SceneState s;
  s.time_s = r.f64();
  s.dt_s = r.f64();
  s.frame_index = r.u64();
  s.bounding_radius = r.f64();
  s.camera = read_camera(r);
  for (double& x : s.camera_lo.eye) x = r.f64();
  for (double& x : s.camera_lo.target) x = r.f64();
  if (r.u32() != param_count || r.failed()) return false;
  for (size_t i = 0; i < param_count; ++i) s.params.push_back(read_value(r));
  if (r.u32() != light_count || r.failed()) return false;
  for (size_t i = 0; i < light_count; ++i) s.lights.push_back(read_light(r));
  if (r.failed()) return false;
  *state = std::move(s);
  return true;
}

void write_messages(WireWriter& w, const std::vector<PluginMessage>& messages) {
  w.u32(static_cast<uint32_t>(messages.size()));
  for (const PluginMessage& m : messages) {
    w.i32(m.level);
    w.str(m.text);
  }
}

bool read_messages(WireReader& r, std::vector<PluginMessage>* messages) {
  const uint32_t n = r.u32();
  if (r.failed() || n > kMaxMessagesPerCall) return false;
  for (uint32_t i = 0; i < n; ++i) {
    PluginMessage m;
    m.level = r.i32();
    m.text = r.str(kMaxMessageBytes);
    messages->push_back(std::move(m));
  }
  return !r.failed();
}

}  // namespace fr
