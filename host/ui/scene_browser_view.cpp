#include "ui/scene_browser_view.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstring>

namespace fr {
namespace {

bool pressed(ImGuiKey key) {
  return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key));
}

// A cell as wide as a thumbnail (rendered at 192 x 108), scaled with the overlay's text.
float browser_cell_width(float scale) {
  return 192 * std::max(scale, 1.0f);
}

}  // namespace

void draw_scene_browser(SceneBrowser& browser, Explorer& explorer, Window& window,
                        BrowserViewState& view) {
  if (!browser.visible()) return;
  const ImGuiIO& io = ImGui::GetIO();
  const float scale = io.FontGlobalScale;
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(io.DisplaySize);
  ImGui::SetNextWindowBgAlpha(0.94f);
  ImGui::Begin("Scenes###browser", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings);
  ImGui::SetWindowFocus();

  // The search field keeps the keyboard: whatever is typed searches.
  if (!ImGui::IsAnyItemActive()) ImGui::SetKeyboardFocusHere();
  ImGui::SetNextItemWidth(std::min(480 * scale, ImGui::GetContentRegionAvail().x));
  const bool enter =
      ImGui::InputTextWithHint("##search", "type to search names, families, descriptions",
                               view.query.data(), view.query.size(),
                               ImGuiInputTextFlags_EnterReturnsTrue);
  browser.set_query(view.query.data());
  int failed = 0;
  for (const BrowserEntry& e : browser.entries()) failed += !browser.failed_reason(e).empty();
  ImGui::TextDisabled("%zu of %zu shown, %d failed%s  |  arrows and Enter open, Esc closes",
                      browser.shown().size(), browser.entries().size(), failed,
                      browser.pending() ? ", pictures on the way" : "");
  if (browser.preparing_scenes() > 0)
    ImGui::TextColored(ImVec4(0.6f, 0.8f, 1, 1),
                       "preparing scenes: %d of %d ready (a test render of each, on the first "
                       "start only)",
                       browser.library_scenes() - browser.preparing_scenes(),
                       browser.library_scenes());
  for (const std::string& problem : browser.cache().problems())
    ImGui::TextColored(ImVec4(1, 0.6f, 0.4f, 1), "%s", problem.c_str());
  if (!view.message.empty()) ImGui::TextColored(ImVec4(1, 0.45f, 0.45f, 1), "%s", view.message.c_str());

  const float cell_w = browser_cell_width(scale);
  const float gap = 10 * scale;
  ImGui::BeginChild("grid");
  view.columns = std::max(1, static_cast<int>((ImGui::GetContentRegionAvail().x + gap) /
                                              (cell_w + gap)));
  if (pressed(ImGuiKey_RightArrow)) browser.move(1);
  if (pressed(ImGuiKey_LeftArrow)) browser.move(-1);
  if (pressed(ImGuiKey_DownArrow)) browser.move(view.columns);
  if (pressed(ImGuiKey_UpArrow)) browser.move(-view.columns);
  int open = enter ? browser.selected() : -1;
  view.cells.clear();
  const std::vector<int>& shown = browser.shown();
  const float thumb_h = cell_w * 9 / 16;
  for (size_t pos = 0; pos < shown.size(); ++pos) {
    const BrowserEntry& entry = browser.entries()[shown[pos]];
    if (pos % view.columns != 0) ImGui::SameLine(0, gap);
    ImGui::PushID(static_cast<int>(pos));
    ImGui::BeginGroup();
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const bool selected = static_cast<int>(pos) == browser.selected();
    if (ImGui::InvisibleButton("cell", ImVec2(cell_w, thumb_h))) open = static_cast<int>(pos);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const RgbaImage* picture = browser.thumbnail(entry);
    void* texture = picture ? window.picture_texture(entry.thumbnail_key, picture->width_px,
                                                     picture->height_px, picture->rgba8.data())
                            : nullptr;
    const ImVec2 end(at.x + cell_w, at.y + thumb_h);
    if (texture)
      draw->AddImage(texture, at, end);
    else
      draw->AddRectFilled(at, end, IM_COL32(40, 40, 46, 255));
    const std::string why = browser.failed_reason(entry);
    if (!texture)
      draw->AddText(ImVec2(at.x + 6 * scale, at.y + 6 * scale),
                    why.empty() ? IM_COL32(150, 150, 150, 255) : IM_COL32(255, 110, 110, 255),
                    !why.empty() ? "failed" : entry.preparing ? "preparing..." : "rendering...");
    if (selected || ImGui::IsItemHovered())
      draw->AddRect(ImVec2(at.x - 2, at.y - 2), ImVec2(end.x + 2, end.y + 2),
                    selected ? IM_COL32(255, 200, 60, 255) : IM_COL32(160, 160, 160, 255), 0,
                    0, 3 * scale);
    if (selected && view.scrolled_to != browser.selected()) {
      ImGui::SetScrollHereY(0.5f);
      view.scrolled_to = browser.selected();
    }
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + cell_w);
    ImGui::TextUnformatted(entry.title.c_str());
    ImGui::TextDisabled("%s%s", entry.family.c_str(), entry.preset_id.empty() ? "" : " preset");
    if (!why.empty())
      ImGui::TextColored(ImVec4(1, 0.45f, 0.45f, 1), "%s", why.c_str());
    else
      ImGui::TextWrapped("%s", entry.description.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndGroup();
    view.cells.push_back({entry.preset_id.empty() ? entry.scene_id
                                                  : entry.scene_id + "--" + entry.preset_id,
                          at.x, at.y, cell_w, thumb_h});
    ImGui::PopID();
  }
  ImGui::EndChild();
  if (pressed(ImGuiKey_Escape)) browser.set_visible(false);
  ImGui::End();
  if (open >= 0) {
    std::string error;
    if (browser.open(open, explorer, &error))
      view.message.clear();
    else
      view.message = error;
  }
}

}  // namespace fr
