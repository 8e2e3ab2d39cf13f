// Params tables: parsing, validation, defaults, and the registry's consistency.
#include <gtest/gtest.h>

#include <set>

#include "core/cli_common.h"
#include "core/errors.h"
#include "techniques/technique.h"
#include "techniques/assignments.h"
#include "registry/presets.h"
#include "registry/registry.h"

using namespace ssr;

TEST(Params, LinearDefaultsAndSet) {
  auto t = create_technique("linear");
  ParamSet p = t->params();
  const int i = p.find("linear.max_steps");
  ASSERT_GE(i, 0);
  EXPECT_EQ(p.find("max_steps"), i);
  EXPECT_EQ(p.get(static_cast<std::size_t>(i)), p.get_default(static_cast<std::size_t>(i)));
  p.set_from_string(static_cast<std::size_t>(i), "64");
  EXPECT_EQ(p.get(static_cast<std::size_t>(i)), 64);
  EXPECT_EQ(p.to_string(static_cast<std::size_t>(i)), "64");
  p.reset_all();
  EXPECT_EQ(p.get(static_cast<std::size_t>(i)), p.get_default(static_cast<std::size_t>(i)));
}

TEST(Params, RejectsBadValues) {
  auto t = create_technique("linear");
  ParamSet p = t->params();
  const auto steps = static_cast<std::size_t>(p.find("max_steps"));
  const auto thick = static_cast<std::size_t>(p.find("thickness"));
  const auto interp = static_cast<std::size_t>(p.find("depth_interp"));
  EXPECT_THROW(p.set_from_string(steps, "0"), InputError);        // below range
  EXPECT_THROW(p.set_from_string(steps, "1e9"), InputError);      // above range
  EXPECT_THROW(p.set_from_string(steps, "2.5"), InputError);      // not whole
  EXPECT_THROW(p.set_from_string(steps, "abc"), InputError);
  EXPECT_THROW(p.set_from_string(steps, ""), InputError);
  EXPECT_THROW(p.set_from_string(thick, "nan"), InputError);
  EXPECT_THROW(p.set_from_string(thick, "inf"), InputError);
  EXPECT_THROW(p.set_from_string(thick, "0.1x"), InputError);
  EXPECT_THROW(p.set_from_string(interp, "maybe"), InputError);
  p.set_from_string(interp, "off");
  EXPECT_EQ(p.get(interp), 0);
  p.set_from_string(interp, "true");
  EXPECT_EQ(p.get(interp), 1);
  try {
    p.set_from_string(steps, "0");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("linear.max_steps"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("[1, 8192]"), std::string::npos);
  }
}

// A float parameter at its minimum survives a copy into another set: 0.0001, stored as the float
// 9.9999997e-5, was refused when the scorer copied the reference's parameters value by value
// through set() (compare with reference.depth_tolerance=0.0001 exited 2 mid-run).
TEST(Params, AFloatAtItsBoundSurvivesACopy) {
  auto a = create_technique("reference");
  auto b = create_technique("reference");
  ParamSet from = a->params(), to = b->params();
  const auto i = static_cast<std::size_t>(from.find("depth_tolerance"));
  from.set_from_string(i, "0.0001");
  EXPECT_LT(from.get(i), 0.0001);                          // stored as the float below it
  EXPECT_THROW(to.set(i, from.get(i)), InputError);         // so set() refuses it, as it should
  to.copy_values_from(from);                                // a copy takes it as stored
  EXPECT_EQ(to.get(i), from.get(i));
  EXPECT_THROW(to.set_from_string(i, "0.0000999999"), InputError);  // below the bound as typed
  auto lin = create_technique("linear");
  EXPECT_THROW(to.copy_values_from(lin->params()), std::logic_error);
}

TEST(Params, Assignments) {
  auto t = create_technique("linear");
  apply_assignments(*t, {"linear.thickness=0.5", "linear.depth_interp=false"});
  ParamSet p = t->params();
  EXPECT_FLOAT_EQ(static_cast<float>(p.get(static_cast<std::size_t>(p.find("thickness")))), 0.5f);
  EXPECT_THROW(apply_assignments(*t, {"linear.nope=1"}), InputError);
  EXPECT_THROW(apply_assignments(*t, {"dda.thickness=1"}), InputError);  // another technique
  EXPECT_THROW(apply_assignments(*t, {"thickness=1"}), InputError);      // no prefix
  EXPECT_THROW(apply_assignments(*t, {"linear.thickness"}), InputError); // no '='
  auto none = create_technique("none");
  EXPECT_THROW(apply_assignments(*none, {"none.x=1"}), InputError);
}

// A preset that says it is the defaults sets nothing else (stochastic-high set 2 rays per quad
// above roughness 0.3 for a while, against the default 4, and still said so).
TEST(Params, PresetsCalledTheDefaultsAreTheDefaults) {
  int checked = 0;
  for (const Preset& preset : presets()) {
    if (preset.source.rfind("the defaults", 0) != 0) continue;
    SCOPED_TRACE(preset.name);
    auto t = create_technique(preset.technique);
    apply_assignments(*t, preset.assignments);
    ParamSet p = t->params();
    for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(p.get(i), p.get_default(i)) << p.key(i);
    ++checked;
  }
  EXPECT_GE(checked, 1);  // stochastic-high
}

TEST(Params, RegistryTablesAreWellFormed) {
  std::set<std::string> names;
  for (const TechniqueInfo& info : technique_registry()) {
    EXPECT_TRUE(names.insert(info.name).second) << info.name;
    auto t = info.create();
    EXPECT_EQ(t->name(), info.name);
    ParamSet p = t->params();
    std::set<std::string> keys;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const ParamDesc& d = p.table()[i];
      EXPECT_TRUE(keys.insert(d.name).second) << p.key(i);
      EXPECT_LE(d.min, d.max) << p.key(i);
      // A default is in range, or "auto" where the parameter takes it; "auto" is no value
      // of the range, so that it cannot be mistaken for one.
      if (d.has_auto()) EXPECT_TRUE(d.auto_value < d.min || d.auto_value > d.max) << p.key(i);
      if (!(d.has_auto() && p.get_default(i) == d.auto_value)) {
        EXPECT_GE(p.get_default(i), d.min) << p.key(i);
        EXPECT_LE(p.get_default(i), d.max) << p.key(i);
      }
      EXPECT_GT(std::string(d.help).size(), 10u) << p.key(i);
      for (char c : std::string(d.name)) EXPECT_TRUE(std::islower(c) || std::isdigit(c) || c == '_') << p.key(i);
    }
  }
  EXPECT_THROW(create_technique("nope"), InputError);
}

TEST(Cli, ParseSize) {
  EXPECT_EQ(parse_size("1280x720"), std::make_pair(1280, 720));
  // Every command takes the size names bench takes (render refused "1080p").
  EXPECT_EQ(parse_size("1080p"), std::make_pair(1920, 1080));
  EXPECT_EQ(parse_size("4k"), parse_size("2160p"));
  EXPECT_EQ(parse_size("8k"), std::make_pair(7680, 4320));
  EXPECT_THROW(parse_size("1080"), InputError);
  EXPECT_THROW(parse_size("4K"), InputError);
  EXPECT_EQ(parse_size("1x1"), std::make_pair(1, 1));
  EXPECT_THROW(parse_size("0x0"), InputError);
  EXPECT_THROW(parse_size("10x0"), InputError);
  EXPECT_THROW(parse_size("-5x5"), InputError);
  EXPECT_THROW(parse_size("1280"), InputError);
  EXPECT_THROW(parse_size("1280x720x3"), InputError);
  EXPECT_THROW(parse_size("9999999x5"), InputError);
}

// "auto" is a value like any other: it parses, prints, resets and is refused where a parameter
// does not take it.
TEST(Params, AutoValues) {
  auto t = create_technique("linear-binary");
  ParamSet p = t->params();
  const std::size_t dist = static_cast<std::size_t>(p.find("max_distance"));
  EXPECT_TRUE(p.is_auto(dist));
  EXPECT_EQ(p.to_string(dist), "auto");
  EXPECT_EQ(p.range_string(dist), "auto|[0.01, 10000]");
  p.set_from_string(dist, "12.5");
  EXPECT_FALSE(p.is_auto(dist));
  EXPECT_DOUBLE_EQ(p.get(dist), 12.5);
  p.set_from_string(dist, "auto");
  EXPECT_TRUE(p.is_auto(dist));
  EXPECT_THROW(p.set_from_string(dist, "Auto"), InputError);
  EXPECT_THROW(p.set(dist, 0.005), InputError);  // below the range, and not the sentinel
  const std::size_t fade = static_cast<std::size_t>(p.find("edge_fade"));
  EXPECT_EQ(p.to_string(fade), "auto");
  EXPECT_EQ(p.range_string(fade), "auto|true|false");
  p.set_from_string(fade, "true");
  EXPECT_EQ(p.to_string(fade), "true");
  p.reset(fade);
  EXPECT_TRUE(p.is_auto(fade));
  const std::size_t steps = static_cast<std::size_t>(p.find("linear_steps"));
  EXPECT_THROW(p.set_from_string(steps, "auto"), InputError);  // a count without auto
}
