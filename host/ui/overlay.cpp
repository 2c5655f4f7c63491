#include "ui/overlay.hpp"

#include "io/atomic_file.hpp"
#include "io/log.hpp"
#include "render/kernel_assembly.hpp"
#include "scene/vec3.hpp"
#include "settings/settings_table.hpp"

#include <imgui.h>
#include <imgui_internal.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace fr {
namespace {

const char* const kSavedFileHeader =
    "Fractalis settings, written by the explorer's \"Save settings\". config/default.toml has "
    "the defaults.";

// Text that wraps at a fixed width (in lines of text, so it scales with the font) rather than at
// the panel's: the panel sizes itself to its widest row, so text wrapped at the panel's width
// would keep a panel that one long message widened that wide after the message went.
void wrapped_text(const ImVec4* color, const std::string& text) {
  constexpr float kWrapEms = 34;
  ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + kWrapEms * ImGui::GetFontSize());
  if (color) ImGui::PushStyleColor(ImGuiCol_Text, *color);
  ImGui::TextUnformatted(text.c_str());
  if (color) ImGui::PopStyleColor();
  ImGui::PopTextWrapPos();
}

// One widget per parameter, by type; true when the value changed.
bool edit_param(const ParamInfo& p, fr_value& v) {
  const char* label = p.name.c_str();
  bool changed = false;
  switch (p.type) {
    case FR_PARAM_FLOAT: {
      float f = static_cast<float>(v.v[0]);
      const ImGuiSliderFlags flags =
          (p.flags & FR_PARAM_LOG_SCALE) ? ImGuiSliderFlags_Logarithmic : 0;
      changed = ImGui::SliderFloat(label, &f, static_cast<float>(p.min_value.v[0]),
                                   static_cast<float>(p.max_value.v[0]), "%.4g", flags);
      if (changed) v.v[0] = f;
      break;
    }
    case FR_PARAM_INT: {
      int i = static_cast<int>(v.v[0]);
      changed = ImGui::SliderInt(label, &i, static_cast<int>(p.min_value.v[0]),
                                 static_cast<int>(p.max_value.v[0]));
      if (changed) v.v[0] = i;
      break;
    }
    case FR_PARAM_CHOICE: {
      const std::string current = p.choice_name(v);
      if (ImGui::BeginCombo(label, current.c_str())) {
        for (size_t c = 0; c < p.choices.size(); ++c) {
          const bool selected = p.choices[c] == current;
          if (ImGui::Selectable(p.choices[c].c_str(), selected) && !selected) {
            v.v[0] = static_cast<double>(c);
            changed = true;
          }
          if (selected) ImGui::SetItemDefaultFocus();
        }
        ImGui::EndCombo();
      }
      break;
    }
    case FR_PARAM_BOOL: {
      bool b = v.v[0] != 0;
      changed = ImGui::Checkbox(label, &b);
      if (changed) v.v[0] = b ? 1 : 0;
      break;
    }
    case FR_PARAM_COLOR: {
      std::array<float, 3> c = to_float3(v.v);
      changed = ImGui::ColorEdit3(label, c.data());
      if (changed) v = fr_value{{c[0], c[1], c[2]}};
      break;
    }
    default: {
      std::array<float, 3> c = to_float3(v.v);
      changed = ImGui::DragFloat3(label, c.data(), 0.01f, static_cast<float>(p.min_value.v[0]),
                                  static_cast<float>(p.max_value.v[0]));
      if (changed) v = fr_value{{c[0], c[1], c[2]}};
      break;
    }
  }
  if (!p.description.empty() && ImGui::IsItemHovered())
    ImGui::SetTooltip("%s", p.description.c_str());
  return changed;
}

// The widget a settings key declares in its table row; true when the value changed.
bool edit_setting(const SettingSpec& spec, Settings& settings) {
  const SettingValue value = spec.get(settings);
  SettingValue edited = value;
  bool changed = false;
  switch (spec.kind) {
    case SettingKind::Bool: {
      bool b = std::get<bool>(value);
      if ((changed = ImGui::Checkbox(spec.label, &b))) edited = b;
      break;
    }
    case SettingKind::Int: {
      int i = static_cast<int>(std::get<long long>(value));
      changed = ImGui::SliderInt(spec.label, &i, static_cast<int>(spec.ui_min),
                                 static_cast<int>(spec.ui_max));
      if (changed) edited = static_cast<long long>(i);
      break;
    }
    case SettingKind::Number: {
      float f = static_cast<float>(std::get<double>(value));
      changed = ImGui::SliderFloat(spec.label, &f, static_cast<float>(spec.ui_min),
                                   static_cast<float>(spec.ui_max), "%.3g",
                                   spec.ui_log ? ImGuiSliderFlags_Logarithmic : 0);
      if (changed) edited = static_cast<double>(f);
      break;
    }
    case SettingKind::Choice: {
      std::vector<const char*> labels;
      int current = 0;
      for (const SettingChoice& c : spec.choices) {
        if (std::get<std::string>(value) == c.name) current = static_cast<int>(labels.size());
        labels.push_back(c.label);
      }
      changed = ImGui::Combo(spec.label, &current, labels.data(), static_cast<int>(labels.size()));
      if (changed) edited = std::string(spec.choices[current].name);
      break;
    }
    case SettingKind::Color: {
      const SettingColor c = std::get<SettingColor>(value);
      float rgb[3] = {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
      changed = ImGui::ColorEdit3(spec.label, rgb, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
      if (changed) edited = SettingColor{rgb[0], rgb[1], rgb[2]};
      break;
    }
    default:
      return false;  // text settings are not in the overlay
  }
  // A slider can be typed into (Ctrl+click) past its range: keep only what a file could hold.
  if (!changed || !check_setting(spec, edited).empty()) return false;
  spec.set(settings, edited);
  return true;
}

// A section's header; every section open when the overlay asks (the tests' view of all labels).
bool section(const OverlayState& overlay, const char* name, ImGuiTreeNodeFlags flags = 0) {
  if (overlay.expand_all) ImGui::SetNextItemOpen(true, ImGuiCond_Always);
  return ImGui::CollapsingHeader(name, flags);
}

void draw_statistics(Explorer& explorer, const OverlayState& overlay) {
  const ExplorerStats& st = explorer.stats();
  if (st.temporal) {
    // Temporal reuse: what this frame traced, and what it carried from the frames before.
    const double n = std::max<double>(
        1, static_cast<double>(st.reuse.fresh + st.reuse.reused + st.reuse.filled));
    ImGui::Text("%.1f ms/frame (%.0f fps), reuse: 1 in %d traced, %.0f%% reused, %.0f%% filled",
                st.frame_ms, st.frame_ms > 0 ? 1000.0 / st.frame_ms : 0.0,
                st.stride_x * st.stride_y, 100 * st.reuse.reused / n, 100 * st.reuse.filled / n);
  } else {
    ImGui::Text("%.1f ms/frame (%.0f fps), scale %.2f, sample %d%s", st.frame_ms,
                st.frame_ms > 0 ? 1000.0 / st.frame_ms : 0.0, st.resolution_scale, st.sample_index,
                st.refined ? " (refined)" : "");
  }
  if (st.path_samples > 0) {
    if (st.path_noise)
      ImGui::Text("path tracing: %d samples per pixel, noise %.2f%% of the brightness",
                  st.path_samples, 100 * *st.path_noise);
    else
      ImGui::Text("path tracing: %d sample%s per pixel%s", st.path_samples,
                  st.path_samples == 1 ? "" : "s", st.path_denoised ? ", denoised" : "");
  }
  // The depth: a pixel's footprint at the nearest surface, and the number type that renders it.
  ImGui::Text("%.1f DE steps/pixel, surface %.4g away, pixel %.2g", st.de_steps_per_pixel,
              st.surface_distance, st.pixel_footprint);
  if (!st.raised_iterations.empty())
    ImGui::Text("for the depth: %s", st.raised_iterations.c_str());
  if (st.past_resolution) {
    const ImVec4 orange(1, 0.6f, 0.2f, 1);
    wrapped_text(&orange, st.pairs_unresolved
                              ? "Past what double resolves here, and this scene's pair estimate "
                                "is only double at these parameters: the picture is not right "
                                "this deep."
                              : "Past what double resolves here, and this scene has no pair "
                                "estimate (scene_de_dd): the picture is not right this deep.");
  }
  // Never silent: rays out of steps and the precision in use, in warning colour when it matters.
  const bool many = 100 * st.out_of_steps_fraction > kOutOfStepsWarnPercent;
  ImGui::TextColored(many ? ImVec4(1, 0.6f, 0.2f, 1) : ImVec4(0.7f, 0.7f, 0.7f, 1),
                     "%.2f%% of rays out of steps%s; %s", 100 * st.out_of_steps_fraction,
                     many ? " (raise Max steps)" : "", precision_name(st.precision));
  if (!section(overlay, "DE evaluations by stage")) return;
  bool counting = explorer.count_evaluations();
  if (ImGui::Checkbox("Count them (a slower kernel)", &counting))
    explorer.set_count_evaluations(counting);
  if (counting && st.eval_counts.samples > 0) {
    ImGui::Text("per pixel, busy lanes, lane evaluations made (lanes %d)", st.eval_counts.lanes);
    for (const StageCount& c : stage_counts(st.eval_counts))
      ImGui::Text("%s %-15s %7.2f %5.1f%% %7.2f",
                  c.bounce == 0 ? "primary " : ("bounce " + std::to_string(c.bounce)).c_str(),
                  c.stage.c_str(), c.evals_per_pixel, 100 * c.utilisation, c.made_per_pixel);
    ImGui::Text("total %24.2f %5.1f%% %7.2f", total_evals_per_pixel(st.eval_counts),
                100 * total_utilisation(st.eval_counts), total_made_per_pixel(st.eval_counts));
  }
}

// The scene list, the current scene's error, and its parameters grouped as it declares them.
void draw_scene(Explorer& explorer, const OverlayState& overlay,
                std::vector<DrawnControl>* controls) {
  auto& slots = explorer.library().slots();
  if (ImGui::BeginCombo("Scene", explorer.current().scene->info.name.c_str())) {
    for (int i = 0; i < static_cast<int>(slots.size()); ++i) {
      std::string label = slots[i].scene->info.name + (slots[i].removed     ? " (removed)"
                                                       : slots[i].preparing ? " (preparing)"
                                                       : slots[i].refused   ? " (failed)"
                                                                            : "");
      if (ImGui::Selectable(label.c_str(), i == explorer.current_index())) explorer.select_scene(i);
    }
    ImGui::EndCombo();
  }
  SceneSlot& slot = explorer.current();
  if (!slot.error.empty()) {
    const ImVec4 red(1, 0.45f, 0.35f, 1);
    wrapped_text(&red, slot.error);
  }
  const SceneInfo& info = slot.scene->info;
  std::map<std::string, std::vector<int>> groups;
  for (int i = 0; i < static_cast<int>(info.params.size()); ++i)
    groups[info.params[i].group].push_back(i);
  for (const auto& [group, indices] : groups) {
    if (!section(overlay, group.empty() ? "Parameters" : group.c_str(),
                 ImGuiTreeNodeFlags_DefaultOpen))
      continue;
    for (int i : indices) {
      ImGui::PushID(i);
      const ImVec2 at = ImGui::GetCursorScreenPos();
      const float width_px = ImGui::CalcItemWidth();
      if (edit_param(info.params[i], slot.state.params[i])) {
        clamp_params(info, slot.state.params);
        explorer.mark_changed();
      }
      controls->push_back({info.params[i].key, at.x, at.y, width_px, ImGui::GetItemRectSize().y});
      ImGui::PopID();
    }
  }
}

void draw_rendering(Explorer& explorer, const OverlayState& overlay) {
  if (!section(overlay, "Rendering")) return;
  bool changed = false;
  ImGui::TextDisabled("this scene uses: %s",
                      stage_names(explorer.current().scene->info.features).c_str());
  for (const SettingSpec& spec : settings_table())
    if (spec.label) changed |= edit_setting(spec, explorer.settings());
  if (changed) explorer.mark_changed();
  // Written atomically (temporary file, then rename): a crash never leaves half a file.
  if (!overlay.settings_file.empty() && ImGui::Button("Save settings")) {
    std::error_code ec;
    std::filesystem::create_directories(overlay.settings_file.parent_path(), ec);
    std::string error;
    if (write_file_atomic(overlay.settings_file,
                          format_settings_toml(explorer.settings(), kSavedFileHeader), &error))
      spdlog::info("saved settings to {}", overlay.settings_file.string());
    else
      spdlog::error("{}", error);
  }
}

void draw_camera(Explorer& explorer, OverlayState& overlay) {
  if (!section(overlay, "Camera", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const KeyBindings& keys = overlay.keys;
  fr_camera& c = explorer.current().state.camera;
  ImGui::Text("eye    %.4f, %.4f, %.4f", c.eye[0], c.eye[1], c.eye[2]);
  ImGui::Text("target %.4f, %.4f, %.4f", c.target[0], c.target[1], c.target[2]);
  ImGui::Text("mode: %s (%s), mouse look: %s (%s)",
              explorer.camera_mode() == CameraMode::Fly ? "fly" : "orbit",
              keys.label(Action::ToggleCameraMode).c_str(), explorer.mouse_look() ? "on" : "off",
              keys.label(Action::ToggleMouseLook).c_str());
  float fov = static_cast<float>(c.fov_deg);
  if (ImGui::SliderFloat("Field of view", &fov, 10, 120, "%.0f deg")) {
    c.fov_deg = fov;
    explorer.mark_changed();
  }
  if (ImGui::Button("Bookmark view")) overlay.bookmarks.push_back(c);
  for (size_t i = 0; i < overlay.bookmarks.size(); ++i) {
    ImGui::SameLine();
    ImGui::PushID(static_cast<int>(i));
    if (ImGui::Button(std::to_string(i + 1).c_str())) {
      c = overlay.bookmarks[i];
      explorer.mark_changed();
    }
    ImGui::PopID();
  }
  if (ImGui::Button("Reset view")) {
    c = explorer.current().scene->info.camera;
    explorer.mark_changed();
  }
}

void draw_camera_path(Explorer& explorer, OverlayState& overlay) {
  if (!section(overlay, "Camera path")) return;
  const KeyBindings& keys = overlay.keys;
  const SceneInfo& info = explorer.current().scene->info;
  PathRecorder& path = explorer.path();
  const size_t keyframes = path.scene_id == info.id ? path.keyframes.size() : 0;
  ImGui::Text("%zu keyframes%s", keyframes,
              path.playing ? fmt::format(", playing: {:.1f} s", path.play_s).c_str() : "");
  float spacing = static_cast<float>(path.spacing_s);
  if (ImGui::SliderFloat("Seconds between keyframes", &spacing, 0.1f, 30.0f, "%.1f s",
                         ImGuiSliderFlags_Logarithmic))
    path.spacing_s = spacing;
  // Labels name the keys in force; "###id" keeps ImGui's id the same whatever the label says.
  const std::string add = "Add keyframe (" + keys.label(Action::AddKeyframe) + ")###add";
  if (ImGui::Button(add.c_str())) add_keyframe(path, info, explorer.current().state);
  ImGui::SameLine();
  if (ImGui::Button("Remove last")) remove_last_keyframe(path);
  ImGui::SameLine();
  const std::string play =
      std::string(path.playing ? "Stop (" : "Play (") + keys.label(Action::PlayPath) + ")###play";
  if (ImGui::Button(play.c_str())) toggle_playback(path, info);
  ImGui::InputText("File", overlay.path_file.data(), overlay.path_file.size());
  std::string error;
  if (ImGui::Button("Save path")) {
    if (save_recorded_path(path, info, overlay.path_file.data(), &error))
      spdlog::info("saved the camera path to {}", overlay.path_file.data());
    else
      spdlog::error("cannot save the path: {}", error);
  }
  ImGui::SameLine();
  if (ImGui::Button("Load path")) {
    if (load_recorded_path(path, info, overlay.path_file.data(), &error))
      spdlog::info("loaded {} keyframes from {}", path.keyframes.size(), overlay.path_file.data());
    else
      spdlog::error("cannot load the path: {}", error);
  }
}

void draw_screenshot(OverlayState& overlay) {
  if (!section(overlay, "Screenshot")) return;
  ImGui::Checkbox("At window size", &overlay.screenshot_at_window_size);
  if (!overlay.screenshot_at_window_size) ImGui::InputInt2("Size", overlay.screenshot_size.data());
  ImGui::InputText("Screenshot file", overlay.screenshot_file.data(),
                   overlay.screenshot_file.size());
  const std::string shot =
      "Save screenshot (" + overlay.keys.label(Action::Screenshot) + ")###shot";
  if (ImGui::Button(shot.c_str())) overlay.screenshot_requested = true;
  ImGui::SameLine();
  ImGui::TextUnformatted(".png, or .exr with passes");
}

// What the panel laid out this frame (CursorMaxPos: the extent of everything, labels past the
// edge included).
OverlayLayout measure_layout() {
  const ImGuiWindow* panel = ImGui::GetCurrentWindow();
  OverlayLayout l;
  l.font_px = ImGui::GetFontSize();
  l.panel_width_px = panel->Size.x;
  l.panel_height_px = panel->Size.y;
  l.content_width_px =
      std::max(panel->DC.IdealMaxPos.x, panel->DC.CursorMaxPos.x) - panel->DC.CursorStartPos.x;
  l.visible_width_px = panel->ContentRegionRect.GetWidth();
  return l;
}

// While the current scene waits for its test render (a first start) or was refused by it: a
// notice in the middle of the window, on top of everything (the foreground draw list: it takes
// no input and no focus), overlay shown or not, so the window is never just black.
void draw_scene_notice(Explorer& explorer) {
  const SceneSlot& slot = explorer.current();
  if (slot.usable()) return;
  SceneLibrary& library = explorer.library();
  const std::string& name =
      slot.scene->info.name.empty() ? slot.scene->info.id : slot.scene->info.name;
  std::string text;
  if (slot.preparing) {
    const int total = static_cast<int>(library.slots().size());
    text = "Preparing " + name +
           ": a test render of its kernel in a child process, once, on a first start.\nScenes "
           "ready: " +
           std::to_string(total - library.preparing()) + " of " + std::to_string(total) + ".";
  } else {
    text = name + " failed its test render: " + slot.error;
  }
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float font_px = ImGui::GetFontSize();
  const float pad = 0.8f * font_px;
  const float wrap_px = std::min(30 * font_px, std::max(display.x - 4 * pad, 4 * font_px));
  const ImVec2 size = ImGui::CalcTextSize(text.c_str(), nullptr, false, wrap_px);
  const ImVec2 at((display.x - size.x) / 2, (display.y - size.y) / 2);
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  draw->AddRectFilled(ImVec2(at.x - pad, at.y - pad), ImVec2(at.x + size.x + pad, at.y + size.y + pad),
                      IM_COL32(20, 20, 26, 230), 0.3f * font_px);
  draw->AddText(nullptr, 0, at,
                slot.preparing ? IM_COL32(220, 225, 235, 255) : IM_COL32(255, 115, 90, 255),
                text.c_str(), nullptr, wrap_px);
}

}  // namespace

void draw_overlay(Explorer& explorer, OverlayState& overlay) {
  draw_scene_notice(explorer);
  if (!overlay.visible) return;
  // The panel takes the width its widest row needs (so no label is cut; the window layer scales
  // text and spacing with the window, ui/window.hpp's overlay_scale) and at most the window's
  // height, scrolling beyond it.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float margin = 10 * ImGui::GetIO().FontGlobalScale;
  ImGui::SetNextWindowPos(ImVec2(margin, margin), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(std::max(display.x - 2 * margin, 1.0f),
                                                           std::max(display.y - 2 * margin, 1.0f)));
  const std::string title =
      "Fractalis (" + overlay.keys.label(Action::ToggleOverlay) + " hides)###main";
  ImGui::Begin(title.c_str(), nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  if (!overlay.edit_status.empty()) {
    const ImVec4 color =
        overlay.edit_failed ? ImVec4(1, 0.45f, 0.35f, 1) : ImVec4(0.6f, 0.9f, 0.6f, 1);
    wrapped_text(&color, overlay.edit_status);
  }
  draw_statistics(explorer, overlay);
  std::vector<DrawnControl> param_controls;
  draw_scene(explorer, overlay, &param_controls);
  draw_rendering(explorer, overlay);
  draw_camera(explorer, overlay);
  draw_camera_path(explorer, overlay);
  draw_screenshot(overlay);
  // The same messages the terminal shows (io/log.hpp), newest last.
  for (const std::string& m : recent_log_messages(8)) wrapped_text(nullptr, m);
  overlay.layout = measure_layout();
  overlay.layout.param_controls = std::move(param_controls);
  ImGui::End();
}

}  // namespace fr
