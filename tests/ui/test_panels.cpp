// The viewer's panels under Dear ImGui's null backend: every technique's parameter panel draws
// one widget (and one reset button) per parameter, clicks change values and 'reset all' restores
// the defaults; the lights, environment and camera panels edit values that still validate.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "viewer/panels.h"
#include "imgui_harness.h"
#include "scene/scene_io.h"
#include "techniques/technique.h"
#include "registry/registry.h"

namespace ssr {
namespace {

using test::ImGuiHarness;
using test::item_id;

Scene test_scene() {
  static const Scene s = load_scene("cornell");
  return s;
}

// The IDs the parameter panel gives its items, computed as it pushes them.
struct ParamIds {
  ImGuiID reset_all = 0;
  std::vector<ImGuiID> widget, reset;
  std::vector<ImGuiID> automatic;  // the "auto" checkbox of parameters that take auto, else 0
};

ImGuiHarness::Draw param_draw(ParamSet& params, ParamIds& ids, const ParamSet* ran = nullptr) {
  return [&params, &ids, ran] {
    ids.reset_all = ImGui::GetID("reset all");
    ids.widget.clear();
    ids.reset.clear();
    ids.automatic.clear();
    for (std::size_t i = 0; i < params.size(); ++i) {
      ids.widget.push_back(item_id({static_cast<int>(i)}, params.table()[i].name));
      ids.reset.push_back(item_id({static_cast<int>(i)}, "reset"));
      ids.automatic.push_back(params.table()[i].has_auto() ? item_id({static_cast<int>(i)}, "##auto") : 0);
    }
    return draw_param_panel(params, ran);
  };
}

bool all_default(const ParamSet& p) {
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.get(i) != p.get_default(i)) return false;
  return true;
}

// (Parameters that take "auto" also draw an "auto" checkbox left of their widget.)
TEST(ParamPanel, EveryTechniqueDrawsOneWidgetAndOneResetPerParameter) {
  for (const TechniqueInfo& info : technique_registry()) {
    SCOPED_TRACE(info.name);
    ImGuiHarness ui;
    auto technique = info.create();
    ParamSet params = technique->params();
    ParamIds ids;
    const auto draw = param_draw(params, ids);
    const auto hits = ui.scan(draw, 10, 3);
    if (params.size() == 0) {
      EXPECT_TRUE(hits.empty()) << "a technique without parameters shows no widgets";
    } else {
      std::set<ImGuiID> expected{ids.reset_all};
      expected.insert(ids.widget.begin(), ids.widget.end());
      expected.insert(ids.reset.begin(), ids.reset.end());
      for (ImGuiID a : ids.automatic)
        if (a) expected.insert(a);
      std::set<ImGuiID> found;
      for (const auto& [id, hit] : hits) found.insert(id);
      EXPECT_EQ(found, expected) << "items other than one widget and one reset per parameter";
      // One row per parameter, top to bottom in table order, its reset button to its right.
      for (std::size_t i = 0; i < params.size(); ++i) {
        SCOPED_TRACE(params.key(i));
        ASSERT_TRUE(hits.count(ids.widget[i]) && hits.count(ids.reset[i]));
        const auto& w = hits.at(ids.widget[i]);
        const auto& r = hits.at(ids.reset[i]);
        EXPECT_GT(r.min.x, w.max.x);
        EXPECT_LT(std::abs(r.center().y - w.center().y), 4.0f);
        if (ids.automatic[i]) {
          ASSERT_TRUE(hits.count(ids.automatic[i]));
          EXPECT_LT(hits.at(ids.automatic[i]).max.x, w.min.x);
        }
        if (i > 0) EXPECT_GT(w.min.y, hits.at(ids.widget[i - 1]).max.y);
      }
    }
    EXPECT_TRUE(all_default(params)) << "hovering changed a value";
    EXPECT_TRUE(ui.errors().empty()) << ui.errors().front();
  }
}

// Moves every parameter away from its default with the mouse (slider ends, checkbox clicks,
// another combo item), then 'reset all' brings all of them back.
TEST(ParamPanel, ClicksChangeValuesAndResetAllRestoresDefaults) {
  int checkboxes = 0, combos = 0;
  for (const TechniqueInfo& info : technique_registry()) {
    SCOPED_TRACE(info.name);
    ImGuiHarness ui;
    auto technique = info.create();
    ParamSet params = technique->params();
    if (params.size() == 0) continue;
    ParamIds ids;
    const auto draw = param_draw(params, ids);
    const auto hits = ui.scan(draw, 10, 3);
    for (std::size_t i = 0; i < params.size(); ++i) {
      SCOPED_TRACE(params.key(i));
      const ParamDesc& d = params.table()[i];
      // An "auto" parameter: untick auto first; its widget then starts from a value of the range.
      if (params.is_auto(i)) {
        EXPECT_TRUE(ui.click(ui.exact(ids.automatic[i], hits.at(ids.automatic[i]), draw).center(), draw));
        EXPECT_FALSE(params.is_auto(i)) << "unticking auto gives a value";
      }
      const double def = params.get(i);
      const auto hit = ui.exact(ids.widget[i], hits.at(ids.widget[i]), draw);
      switch (d.type) {
        case ParamType::Float:
        case ParamType::Int: {
          // A click on a slider's far end sets that end of the range.
          const bool to_max = d.max - def >= def - d.min;
          EXPECT_TRUE(ui.click(to_max ? hit.right() : hit.left(), draw));
          EXPECT_EQ(params.get(i), to_max ? d.max : d.min);
          break;
        }
        case ParamType::Bool: {
          ++checkboxes;
          EXPECT_TRUE(ui.click(hit.center(), draw));
          EXPECT_EQ(params.get(i), 1 - def) << "the checkbox toggles";
          EXPECT_TRUE(ui.click(hit.center(), draw));
          EXPECT_EQ(params.get(i), def) << "and toggles back";
          EXPECT_TRUE(ui.click(hit.center(), draw));
          break;
        }
        case ParamType::Choice: {
          ++combos;
          ui.click(hit.center(), draw);  // opens the list
          ui.frame(draw);                 // popups are sized on their first frame, shown on the next
          ImGuiWindow* popup = ImGui::FindWindowByName("##Combo_00");
          ASSERT_NE(popup, nullptr);
          ASSERT_TRUE(popup->Active);
          // The items are the popup's rows, in order; pick the one after the current one.
          std::vector<std::pair<ImGuiID, float>> rows;
          for (float y = popup->Pos.y + 1; y < popup->Pos.y + popup->Size.y; y += 2) {
            ui.move(ImVec2(popup->Pos.x + 10, y));
            ui.frame(draw);
            const ImGuiID id = ImGuiHarness::hovered();
            if (id && (rows.empty() || rows.back().first != id)) rows.emplace_back(id, y);
          }
          ASSERT_EQ(rows.size(), d.choices.size());
          const std::size_t pick = (static_cast<std::size_t>(def) + 1) % d.choices.size();
          EXPECT_TRUE(ui.click(ImVec2(popup->Pos.x + 10, rows[pick].second + 1), draw));
          EXPECT_EQ(params.get(i), static_cast<double>(pick));
          break;
        }
      }
    }
    // Every value differs from its default now (ranges never collapse to the default).
    for (std::size_t i = 0; i < params.size(); ++i)
      EXPECT_NE(params.get(i), params.get_default(i)) << params.key(i);
    // A parameter's own reset button.
    EXPECT_TRUE(ui.click(hits.at(ids.reset[0]).center(), draw));
    EXPECT_EQ(params.get(0), params.get_default(0));
    if (params.size() > 1) EXPECT_NE(params.get(1), params.get_default(1));
    // 'reset all'.
    EXPECT_TRUE(ui.click(hits.at(ids.reset_all).center(), draw));
    EXPECT_TRUE(all_default(params));
    // Now disabled: clicking it changes nothing.
    EXPECT_FALSE(ui.click(hits.at(ids.reset_all).center(), draw));
    EXPECT_TRUE(ui.errors().empty()) << ui.errors().front();
  }
  EXPECT_GT(checkboxes, 0) << "no technique has a checkbox: the test lost its reach";
  EXPECT_GT(combos, 0) << "no technique has a choice: the test lost its reach";
}

// Unticking "auto" starts from the value auto ran with: it jumped to the range's geometric mean,
// dda's max_steps from 734 (640x360) to 91, which cut corridor's floor reflections short.
TEST(ParamPanel, UntickingAutoStartsFromWhatAutoRanWith) {
  ImGuiHarness ui;
  auto technique = create_technique("dda");
  auto last_run = create_technique("dda");  // stands for ran_params() after a frame
  ParamSet params = technique->params(), ran = last_run->params();
  const int i = params.find("max_steps");
  ASSERT_GE(i, 0);
  ASSERT_TRUE(params.is_auto(static_cast<std::size_t>(i)));
  ran.set(static_cast<std::size_t>(i), 734);
  ParamIds ids;
  const auto draw = param_draw(params, ids, &ran);
  const auto hits = ui.scan(draw, 10, 3);
  const ImGuiID box = ids.automatic[static_cast<std::size_t>(i)];
  EXPECT_TRUE(ui.click(ui.exact(box, hits.at(box), draw).center(), draw));
  EXPECT_EQ(params.get(static_cast<std::size_t>(i)), 734.0);
  EXPECT_TRUE(ui.errors().empty()) << ui.errors().front();
}

// Before a run, ran_params() is params() (it was the table's defaults: "auto" for a value set).
TEST(ParamPanel, RanParamsBeforeARunAreTheParameters) {
  auto hiz = create_technique("hiz");
  ParamSet p = hiz->params();
  const std::size_t i = static_cast<std::size_t>(p.find("max_iterations"));
  p.set(i, 64);
  EXPECT_EQ(hiz->ran_params().get(i), 64.0);
}

// ---- lights ---------------------------------------------------------------------------------

struct LightIds {
  ImGuiID add = 0;
  std::vector<ImGuiID> point, directional, remove, range, intensity, yaw, pitch;
};

ImGuiHarness::Draw lights_draw(std::vector<Light>& lights, LightIds& ids) {
  return [&lights, &ids] {
    ids = {};
    ids.add = ImGui::GetID("add light");
    for (std::size_t i = 0; i < lights.size(); ++i) {
      const int n = static_cast<int>(i);
      ids.point.push_back(item_id({n, "light"}, "point"));
      ids.directional.push_back(item_id({n, "light"}, "directional"));
      ids.remove.push_back(item_id({n, "light"}, "remove"));
      ids.range.push_back(item_id({n, "light"}, "range"));
      ids.intensity.push_back(item_id({n, "light"}, "intensity"));
      ids.yaw.push_back(item_id({n, "light"}, "yaw"));
      ids.pitch.push_back(item_id({n, "light"}, "pitch"));
    }
    return draw_lights_panel(lights);
  };
}

void expect_valid_lights(const std::vector<Light>& lights) {
  Scene s = test_scene();
  s.lights = lights;
  EXPECT_NO_THROW(validate(s));
  for (const Light& l : lights)
    if (l.type == Light::Type::Directional) EXPECT_NEAR(glm::length(l.direction), 1.0f, 1e-5f);
}

TEST(LightsPanel, EditsKeepTheSceneValid) {
  ImGuiHarness ui;
  std::vector<Light> lights(2);
  lights[0].position = {1, 2, 3};
  lights[1].type = Light::Type::Directional;
  lights[1].direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  LightIds ids;
  const auto draw = lights_draw(lights, ids);
  auto hits = ui.scan(draw);

  // Dragging right raises the intensity and the range.
  EXPECT_TRUE(ui.drag(hits.at(ids.intensity[0]).center(), 60, draw));
  EXPECT_GT(lights[0].intensity, 1.0f);
  EXPECT_TRUE(ui.drag(hits.at(ids.range[0]).center(), 60, draw));
  EXPECT_GT(lights[0].range, 20.0f);
  // Dragging the intensity far left stops at 0, which validate() accepts.
  EXPECT_TRUE(ui.drag(hits.at(ids.intensity[1]).center(), -700, draw));
  EXPECT_EQ(lights[1].intensity, 0.0f);
  // Yaw and pitch turn the directional light; its direction stays a unit vector.
  const glm::vec3 before = lights[1].direction;
  EXPECT_TRUE(ui.click(ui.exact(ids.yaw[1], hits.at(ids.yaw[1]), draw).left(), draw));
  EXPECT_TRUE(ui.click(ui.exact(ids.pitch[1], hits.at(ids.pitch[1]), draw).right(), draw));
  EXPECT_GT(glm::length(lights[1].direction - before), 0.1f);
  EXPECT_NEAR(lights[1].direction.y, 1.0f, 1e-3f) << "pitch at its top end points up";
  expect_valid_lights(lights);

  // The point light becomes directional: its (default) direction is a unit vector.
  EXPECT_FALSE(ui.click(hits.at(ids.point[0]).center(), draw)) << "its own type again: no change";
  EXPECT_TRUE(ui.click(hits.at(ids.directional[0]).center(), draw));
  EXPECT_EQ(lights[0].type, Light::Type::Directional);
  expect_valid_lights(lights);

  // Add, then remove the first light.
  hits = ui.scan(draw);
  EXPECT_TRUE(ui.click(hits.at(ids.add).center(), draw));
  ASSERT_EQ(lights.size(), 3u);
  EXPECT_EQ(lights[2].type, Light::Type::Point);
  const Light second = lights[1];
  hits = ui.scan(draw);
  EXPECT_TRUE(ui.click(hits.at(ids.remove[0]).center(), draw));
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights[0].direction, second.direction);
  expect_valid_lights(lights);
  EXPECT_TRUE(ui.errors().empty()) << ui.errors().front();
}

TEST(LightsPanel, AddStopsAtTheMaximum) {
  ImGuiHarness ui;
  std::vector<Light> lights(static_cast<std::size_t>(Scene::kMaxLights) - 1);
  LightIds ids;
  const auto draw = lights_draw(lights, ids);
  ui.frame(draw);
  auto hits = ui.scan(draw, 50, 3, ui.bottom() - 60);  // the add button is last
  EXPECT_TRUE(ui.click(hits.at(ids.add).center(), draw));
  ASSERT_EQ(lights.size(), static_cast<std::size_t>(Scene::kMaxLights));
  ui.frame(draw);
  hits = ui.scan(draw, 50, 3, ui.bottom() - 60);
  EXPECT_FALSE(ui.click(hits.at(ids.add).center(), draw)) << "disabled at the maximum";
  EXPECT_EQ(lights.size(), static_cast<std::size_t>(Scene::kMaxLights));
  expect_valid_lights(lights);
  EXPECT_TRUE(ui.errors().empty()) << ui.errors().front();
}

// ---- environment and camera -----------------------------------------------------------------

TEST(EnvironmentPanel, EditsKeepTheSceneValid) {
  ImGuiHarness ui;
  Environment env;
  float ambient = 0.3f;
  ImGuiID sky = 0, constant = 0, intensity = 0, ambient_id = 0;
  const ImGuiHarness::Draw draw = [&] {
    sky = ImGui::GetID("sky");
    constant = ImGui::GetID("constant");
    intensity = ImGui::GetID("intensity");
    ambient_id = ImGui::GetID("ambient");
    return draw_environment_panel(env, ambient);
  };
  auto hits = ui.scan(draw);
  EXPECT_TRUE(ui.drag(hits.at(intensity).center(), 50, draw));
  EXPECT_GT(env.intensity, 1.0f);
  EXPECT_TRUE(ui.drag(hits.at(ambient_id).center(), -700, draw));
  EXPECT_EQ(ambient, 0.0f) << "ambient stops at 0";
  EXPECT_TRUE(ui.click(hits.at(constant).center(), draw));
  EXPECT_EQ(env.type, Environment::Type::Constant);
  hits = ui.scan(draw);  // the colours changed: constant has one
  EXPECT_TRUE(ui.click(hits.at(sky).center(), draw));
  EXPECT_EQ(env.type, Environment::Type::Sky);
  Scene s = test_scene();
  s.environment = env;
  s.ambient = ambient;
  EXPECT_NO_THROW(validate(s));
  EXPECT_FALSE(ui.click(ImVec2(790, 5990), draw)) << "a click on nothing changes nothing";
  EXPECT_TRUE(ui.errors().empty()) << ui.errors().front();
}

TEST(CameraPanel, EditsKeepTheCameraValid) {
  ImGuiHarness ui;
  Camera cam = test_scene().cameras.front();
  ImGuiID fov = 0, near_id = 0, far_id = 0;
  const ImGuiHarness::Draw draw = [&] {
    fov = ImGui::GetID("fov y");
    near_id = ImGui::GetID("near");
    far_id = ImGui::GetID("far");
    return draw_camera_panel(cam);
  };
  const auto hits = ui.scan(draw);
  EXPECT_TRUE(ui.click(ui.exact(fov, hits.at(fov), draw).right(), draw));
  EXPECT_EQ(cam.fov_y_deg, 150.0f);
  // Near dragged far right stops below far; far dragged far left stops above near.
  EXPECT_TRUE(ui.drag(hits.at(near_id).center(), 700, draw));
  EXPECT_TRUE(ui.drag(hits.at(far_id).center(), -700, draw));
  EXPECT_GT(cam.near_plane, 0.0f);
  EXPECT_GT(cam.far_plane, cam.near_plane);
  Scene s = test_scene();
  s.cameras = {cam};
  EXPECT_NO_THROW(validate(s));
  EXPECT_TRUE(ui.errors().empty()) << ui.errors().front();
}

}  // namespace
}  // namespace ssr
