// The viewer's panels added with the rebuilt viewer, under Dear ImGui's null backend: every
// view's legend draws the colours its image is drawn with (heat and grey bars from
// shared/colormap.h, each swatch), views without a scale draw no bar; the pixel values list
// draws one line a value and a block per side; the status line's toggles act and an error is
// red; the timing table has a row per pass plus the total and its plots are drawn.
#include <gtest/gtest.h>

#include <set>

#include "eval/grid.h"
#include "imgui_harness.h"
#include "shared/colormap.h"
#include "viewer/panels.h"

namespace ssr {
namespace {

using test::ImGuiHarness;

ImU32 rgb(glm::vec3 c) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c.x, c.y, c.z, 1.0f)); }

// Every vertex colour of the last frame.
std::set<ImU32> drawn_colours() {
  std::set<ImU32> out;
  const ImDrawData* d = ImGui::GetDrawData();
  for (int i = 0; d && i < d->CmdListsCount; ++i)
    for (const ImDrawVert& v : d->CmdLists[i]->VtxBuffer) out.insert(v.col);
  return out;
}

// The bar's middle step, as colour_bar samples it.
constexpr float kMid = (32 + 0.5f) / 64;

TEST(Legends, EveryViewDrawsItsScaleOrSwatches) {
  ImGuiHarness ui;
  for (const ViewInfo& v : view_table()) {
    ui.frame([&] {
      draw_view_legend(v, 0.0f);
      return false;
    });
    const std::set<ImU32> c = drawn_colours();
    const bool heat = c.count(rgb(shared::heat(kMid))) > 0, grey = c.count(rgb(glm::vec3(kMid))) > 0;
    switch (v.legend.kind) {
      case Legend::Heat:
        EXPECT_TRUE(heat) << v.name << ": no heat bar";
        break;
      case Legend::Grey:
        EXPECT_TRUE(grey) << v.name << ": no grey bar";
        break;
      case Legend::Swatches:
        EXPECT_GE(v.legend.swatches.size(), 2u) << v.name;
        for (const Legend::Swatch& s : v.legend.swatches)
          EXPECT_TRUE(c.count(rgb(glm::vec3(s.r, s.g, s.b)))) << v.name << ": swatch " << s.name << " not drawn";
        break;
      case Legend::Radiance:
      case Legend::Encoded:
        EXPECT_FALSE(heat || grey) << v.name << ": a bar for a view without a scale";
        break;
    }
    // Every heat-map view says so in its legend (a heat view without one would be unreadable).
    if (std::string(v.description).find("heat map") != std::string::npos) EXPECT_EQ(v.legend.kind, Legend::Heat) << v.name;
  }
  EXPECT_TRUE(ui.errors().empty());
}

TEST(Legends, DifferenceAndClassLegends) {
  ImGuiHarness ui;
  ui.frame([] {
    draw_difference_legend(0.25f);
    return false;
  });
  EXPECT_TRUE(drawn_colours().count(rgb(shared::heat(kMid))));
  ui.frame([] {
    draw_class_legend();
    return false;
  });
  const std::set<ImU32> c = drawn_colours();
  for (const PixelClass k : {PixelClass::Traceable, PixelClass::Missing, PixelClass::Sky})
    EXPECT_TRUE(c.count(rgb(class_colour(k)))) << static_cast<int>(k);
  EXPECT_TRUE(ui.errors().empty());
}

TEST(Legends, PixelValuesOneLineEach) {
  ImGuiHarness ui;
  const nlohmann::ordered_json one = {{"pixel", {1, 2}}, {"depth", 0.5}, {"object", 3}};
  nlohmann::ordered_json two = one;
  two["normal"] = {0.0, 1.0, 0.0};
  two["a"] = {{"technique", "hiz"}, {"current", true}, {"steps", 12.0}, {"display", {1, 2, 3}}};
  two["b"] = {{"technique", "reference"}, {"current", false}, {"error", 0.0}};
  ui.frame([&] {
    draw_pixel_values(one);
    return false;
  });
  const float short_list = ui.bottom();
  ui.frame([&] {
    draw_pixel_values(two);
    return false;
  });
  // One more value line and two sides (a heading and their values): at least 6 more lines.
  EXPECT_GT(ui.bottom() - short_list, 6 * ImGui::GetTextLineHeight());
  EXPECT_TRUE(ui.errors().empty());
}

TEST(StatusLine, TogglesActAndErrorsAreRed) {
  ImGuiHarness ui;
  StatusLine line{"shader error: render/lighting.comp:12: syntax", true, "stale", 12.5, "llvmpipe"};
  StatusActions act;
  ImGuiID panel = 0, keys = 0;  // as ImGui names the buttons, inside the frame
  auto draw = [&] {
    panel = test::item_id({}, "panel >");
    keys = test::item_id({}, "keys");
    act = draw_status_line(line, true);
    return act.toggle_panel || act.toggle_keys;
  };
  ui.frame(draw);
  const ImU32 red = ImGui::ColorConvertFloat4ToU32(ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
  EXPECT_TRUE(drawn_colours().count(red)) << "an error is drawn red";
  line.error = false;
  ui.frame(draw);
  EXPECT_FALSE(drawn_colours().count(red));
  const auto hits = ui.scan(draw);
  ASSERT_TRUE(hits.count(panel) && hits.count(keys));
  EXPECT_TRUE(ui.click(hits.at(panel).center(), [&] { return draw_status_line(line, true).toggle_panel; }));
  EXPECT_TRUE(ui.click(hits.at(keys).center(), [&] { return draw_status_line(line, true).toggle_keys; }));
  EXPECT_FALSE(ui.click(hits.at(keys).center(), [&] { return draw_status_line(line, true).toggle_panel; }));
  EXPECT_TRUE(ui.errors().empty());
}

// The figures on the right keep their place whatever the message: a long or multi-line one is
// clipped to the room left of them (it once pushed them off the window's edge).
TEST(StatusLine, ALongMessageLeavesTheFiguresInPlace) {
  ImGuiHarness ui;
  const ImU32 grey = ImGui::GetColorU32(ImGuiCol_TextDisabled);
  auto figures_span = [&](const std::string& message) {
    const StatusLine line{message, true, "", 12.5, "llvmpipe (LLVM 15.0.6, 256 bits)"};
    ui.frame([&] {
      draw_status_line(line, true);
      return false;
    });
    float lo = FLT_MAX, hi = -FLT_MAX;
    const ImDrawData* d = ImGui::GetDrawData();
    for (int i = 0; d && i < d->CmdListsCount; ++i)
      for (const ImDrawVert& v : d->CmdLists[i]->VtxBuffer)
        if (v.col == grey) lo = std::min(lo, v.pos.x), hi = std::max(hi, v.pos.x);
    return std::pair{lo, hi};
  };
  const auto alone = figures_span("");
  ASSERT_LT(alone.first, alone.second);
  EXPECT_LE(alone.second, ImGuiHarness::kWidth);
  const std::string long_line(400, 'x');
  for (const std::string& m : {long_line, "shader compile failed\nrender/lighting.comp:12:3: " + long_line}) {
    const auto with = figures_span(m);
    EXPECT_FLOAT_EQ(with.first, alone.first);
    EXPECT_FLOAT_EQ(with.second, alone.second);
  }
  EXPECT_TRUE(ui.errors().empty());
}

// The frame's inputs render once, under A: B's column showed no G-buffer or lighting rows and a
// total without them, so whichever side was A looked slower.
TEST(Timing, TheFramesInputsCountInEverySidesTotal) {
  const std::vector<TimingColumn> columns = {
      {"A", "hiz", {{"gbuffer", 0.5}, {"lighting", 0.25}, {"trace", 1.5}}, {}},
      {"B", "linear", {{"march", 3.0}}, {}},
  };
  const TimingTable t = timing_table(columns, true);
  EXPECT_TRUE(t.shared_inputs);
  auto find = [&](const std::string& name) {
    for (const auto& r : t.cells)
      if (r[0] == name) return r;
    ADD_FAILURE() << "no row " << name;
    return std::vector<std::string>(5);
  };
  EXPECT_EQ(find("gbuffer *")[3], "0.500") << "B's column shows the shared input";
  EXPECT_EQ(find("lighting *")[3], "0.250");
  EXPECT_EQ(find("total")[1], "2.25");
  EXPECT_EQ(find("total")[3], "3.75") << "B's total counts the inputs too";
  EXPECT_EQ(find("march")[1], "") << "a technique's own pass is not shared";
  // A side that has not run (the grid's truth before its first trace) shows nothing, not the
  // inputs as if it had run.
  const TimingTable idle = timing_table({columns[0], {"truth", "reference", {}, {}}}, true);
  for (const auto& r : idle.cells)
    if (r[0] == "total" || r[0] == "gbuffer *") EXPECT_EQ(r[3], "") << r[0];
}

TEST(Timing, RowPerPassTotalAndVisiblePlots) {
  ImGuiHarness ui;
  const std::vector<TimingColumn> columns = {
      {"A", "hiz", {{"gbuffer", 0.5}, {"trace", 1.5}}, {1.4f, 1.5f, 1.6f}},
      {"B", "linear", {{"gbuffer", 0.5}, {"march", 3.0}}, {2.9f, 3.0f}},
  };
  std::size_t with_plots = 0, without = 0;
  ui.frame([&] {
    draw_timing(columns, {16.0f, 17.0f}, 17.0, true);
    return false;
  });
  const ImU32 plot = ImGui::GetColorU32(ImGuiCol_PlotLines);
  for (int i = 0; i < ImGui::GetDrawData()->CmdListsCount; ++i)
    for (const ImDrawVert& v : ImGui::GetDrawData()->CmdLists[i]->VtxBuffer) with_plots += v.col == plot;
  ui.frame([&] {
    draw_timing({{"A", "hiz", {{"gbuffer", 0.5}}, {}}}, {}, 0.0, false);
    return false;
  });
  for (int i = 0; i < ImGui::GetDrawData()->CmdListsCount; ++i)
    for (const ImDrawVert& v : ImGui::GetDrawData()->CmdLists[i]->VtxBuffer) without += v.col == plot;
  // Four line segments (A: 2, B: 1, frame: 1), four vertices each; a negative width drew none.
  EXPECT_GE(with_plots, 16u) << "the rolling plots draw no lines";
  EXPECT_EQ(without, 0u);
  EXPECT_TRUE(ui.errors().empty());
}

}  // namespace
}  // namespace ssr
