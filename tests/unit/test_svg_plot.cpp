// SVG plot writer: well-formed output, no NaN/inf, nice ticks, escaping.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "eval/svg_plot.h"

using namespace ssr;

namespace {

std::size_t count(const std::string& s, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t p = s.find(needle); p != std::string::npos; p = s.find(needle, p + 1)) ++n;
  return n;
}

// A tiny well-formedness check: one <svg> root, start and end tags balance as a stack, no
// unescaped '&' or '<' in text, every polyline has points, and no nan/inf anywhere.
void expect_well_formed(const std::string& svg) {
  EXPECT_EQ(count(svg, "<svg"), 1u);
  EXPECT_EQ(count(svg, "</svg>"), 1u);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
  EXPECT_EQ(svg.find("NaN"), std::string::npos);
  EXPECT_EQ(svg.find("Inf"), std::string::npos);

  std::vector<std::string> stack;
  std::size_t i = 0;
  while (i < svg.size()) {
    if (svg[i] == '&') {
      const std::size_t semi = svg.find(';', i);
      ASSERT_NE(semi, std::string::npos);
      const std::string ent = svg.substr(i, semi - i + 1);
      EXPECT_TRUE(ent == "&amp;" || ent == "&lt;" || ent == "&gt;" || ent == "&quot;" ||
                  ent == "&apos;")
          << ent;
      i = semi + 1;
      continue;
    }
    if (svg[i] != '<') {
      EXPECT_NE(svg[i], '>') << "stray '>' at " << i;
      ++i;
      continue;
    }
    const std::size_t end = svg.find('>', i);
    ASSERT_NE(end, std::string::npos);
    const std::string tag = svg.substr(i + 1, end - i - 1);
    ASSERT_FALSE(tag.empty());
    // Inside a tag, attribute values are quoted and contain no '<'.
    EXPECT_EQ(tag.find('<'), std::string::npos) << tag;
    EXPECT_EQ(count(tag, "\"") % 2, 0u) << tag;
    if (tag[0] == '?') {
      // <?xml ...?>
    } else if (tag[0] == '/') {
      ASSERT_FALSE(stack.empty()) << tag;
      EXPECT_EQ(stack.back(), tag.substr(1)) << tag;
      stack.pop_back();
    } else {
      const std::string name = tag.substr(0, tag.find_first_of(" \n/"));
      if (name == "polyline") {
        EXPECT_NE(tag.find("points=\""), std::string::npos) << tag;
      }
      if (tag.back() != '/') stack.push_back(name);
    }
    i = end + 1;
  }
  EXPECT_TRUE(stack.empty());
}

// The texts of the <text> elements with the given class.
std::vector<std::string> texts_of_class(const std::string& svg, const std::string& cls) {
  std::vector<std::string> out;
  const std::string open = "<text class=\"" + cls + "\"";
  for (std::size_t p = svg.find(open); p != std::string::npos; p = svg.find(open, p + 1)) {
    const std::size_t a = svg.find('>', p) + 1;
    const std::size_t b = svg.find("</text>", a);
    out.push_back(svg.substr(a, b - a));
  }
  return out;
}

PlotSpec sample_spec() {
  PlotSpec s;
  s.title = "Time vs error";
  s.x_label = "time (ms)";
  s.y_label = "PSNR (dB)";
  PlotSeries a;
  a.name = "linear";
  a.points = {{0.5, 20.0}, {1.0, 24.0}, {2.0, 27.5}, {4.0, 29.0}};
  a.labels = {"16", "32", "64", "128"};
  PlotSeries b;
  b.name = "hiz";
  b.points = {{0.3, 25.0}, {0.6, 28.0}};
  b.lines = false;
  s.series = {a, b};
  return s;
}

}  // namespace

TEST(SvgPlot, WellFormed) {
  const std::string svg = svg_plot(sample_spec());
  expect_well_formed(svg);
  EXPECT_EQ(count(svg, "<polyline"), 1u);  // only the series with lines
  EXPECT_NE(svg.find("Time vs error"), std::string::npos);
  EXPECT_NE(svg.find("time (ms)"), std::string::npos);
  EXPECT_NE(svg.find("PSNR (dB)"), std::string::npos);
  EXPECT_NE(svg.find(">linear</text>"), std::string::npos);
  EXPECT_NE(svg.find(">hiz</text>"), std::string::npos);
  EXPECT_NE(svg.find(">128</text>"), std::string::npos);  // point label
  EXPECT_EQ(texts_of_class(svg, "point-label").size(), 4u);
  // Two series, two colours.
  EXPECT_NE(svg.find("#0072B2"), std::string::npos);
  EXPECT_NE(svg.find("#D55E00"), std::string::npos);
}

TEST(SvgPlot, LinearTicksAreNice) {
  const std::string svg = svg_plot(sample_spec());
  const auto ys = texts_of_class(svg, "tick-y");
  ASSERT_GE(ys.size(), 3u);
  std::vector<double> v;
  for (const auto& t : ys) v.push_back(std::strtod(t.c_str(), nullptr));
  const double step = v[1] - v[0];
  EXPECT_GT(step, 0.0);
  // The step is 1, 2 or 5 times a power of ten, and constant.
  const double m = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  EXPECT_TRUE(std::fabs(m - 1) < 1e-9 || std::fabs(m - 2) < 1e-9 || std::fabs(m - 5) < 1e-9) << m;
  for (std::size_t i = 1; i < v.size(); ++i) EXPECT_NEAR(v[i] - v[i - 1], step, 1e-9);
  // The ticks cover the data (20..29).
  EXPECT_LE(v.front(), 20.0);
  EXPECT_GE(v.back(), 29.0);
}

TEST(SvgPlot, LogTicksArePowersOfTen) {
  PlotSpec s;
  s.log_x = true;
  s.log_y = true;
  PlotSeries a;
  a.name = "sweep";
  a.points = {{0.03, 2.0}, {0.5, 40.0}, {7.0, 900.0}, {0.0, 5.0}, {-1.0, 3.0}, {2.0, -4.0}};
  s.series = {a};
  const std::string svg = svg_plot(s);
  expect_well_formed(svg);
  for (const char* cls : {"tick-x", "tick-y"}) {
    const auto ticks = texts_of_class(svg, cls);
    ASSERT_GE(ticks.size(), 2u) << cls;
    for (const auto& t : ticks) {
      const double v = std::strtod(t.c_str(), nullptr);
      ASSERT_GT(v, 0.0) << t;
      const double e = std::log10(v);
      EXPECT_NEAR(e, std::round(e), 1e-9) << cls << " " << t;
    }
  }
  const auto xs = texts_of_class(svg, "tick-x");
  EXPECT_EQ(xs.front(), "0.01");
  EXPECT_EQ(xs.back(), "10");
  const auto ys = texts_of_class(svg, "tick-y");
  EXPECT_EQ(ys.front(), "1");
  EXPECT_EQ(ys.back(), "1000");
  // Non-positive values are skipped on a log axis: 3 markers, the line breaks at them.
  EXPECT_EQ(count(svg, "<circle"), 3u + 1u);  // + the legend marker
}

TEST(SvgPlot, EscapesText) {
  PlotSpec s = sample_spec();
  s.title = "a<b&c \"q\" 'x'";
  s.x_label = "x > y";
  s.series[0].name = "a<b&c";
  s.series[0].labels[0] = "<tag>";
  const std::string svg = svg_plot(s);
  expect_well_formed(svg);
  EXPECT_NE(svg.find("a&lt;b&amp;c"), std::string::npos);
  EXPECT_NE(svg.find("a&lt;b&amp;c &quot;q&quot; &apos;x&apos;"), std::string::npos);
  EXPECT_NE(svg.find("x &gt; y"), std::string::npos);
  EXPECT_NE(svg.find("&lt;tag&gt;"), std::string::npos);
  EXPECT_EQ(svg.find("a<b"), std::string::npos);
  EXPECT_EQ(svg.find("<tag>"), std::string::npos);
  EXPECT_EQ(xml_escape("&<>\"'"), "&amp;&lt;&gt;&quot;&apos;");
}

TEST(SvgPlot, NonFinitePointsAreSkipped) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  PlotSpec s;
  PlotSeries a;
  a.name = "holes";
  a.points = {{0, 0}, {1, 1}, {nan, 2}, {3, inf}, {4, 4}, {5, 5}, {-inf, 1}};
  s.series = {a};
  const std::string svg = svg_plot(s);
  expect_well_formed(svg);
  EXPECT_EQ(count(svg, "<polyline"), 2u);  // (0,1) and (4,5): broken at the holes
  EXPECT_EQ(count(svg, "<circle"), 4u + 1u);
}

TEST(SvgPlot, DegenerateInputsStillGiveValidSvg) {
  {
    PlotSpec s;  // no series at all
    expect_well_formed(svg_plot(s));
  }
  {
    PlotSpec s;
    s.series = {PlotSeries{"empty", {}, {}, true}};
    const std::string svg = svg_plot(s);
    expect_well_formed(svg);
    EXPECT_EQ(count(svg, "<polyline"), 0u);
  }
  for (bool log : {false, true}) {
    PlotSpec s;
    s.log_x = s.log_y = log;
    s.series = {PlotSeries{"one", {{2.0, 3.0}}, {"only"}, true}};
    const std::string svg = svg_plot(s);
    expect_well_formed(svg);
    EXPECT_EQ(count(svg, "<polyline"), 0u);
    EXPECT_GE(texts_of_class(svg, "tick-x").size(), 2u);
    EXPECT_GE(texts_of_class(svg, "tick-y").size(), 2u);
  }
  {
    PlotSpec s;  // all points at zero, and all values equal
    s.series = {PlotSeries{"zero", {{0.0, 0.0}, {0.0, 0.0}}, {}, true},
                PlotSeries{"same", {{5.0, 0.0}, {5.0, 0.0}}, {}, true}};
    expect_well_formed(svg_plot(s));
  }
  {
    PlotSpec s;  // only unusable points on a log axis
    s.log_y = true;
    s.series = {PlotSeries{"neg", {{1.0, -1.0}, {2.0, 0.0}}, {}, true}};
    expect_well_formed(svg_plot(s));
  }
  {
    PlotSpec s;  // extreme magnitudes
    s.series = {PlotSeries{"huge", {{-1e300, 1e-300}, {1e300, 2e-300}, {1e308, 1.0}}, {}, true}};
    expect_well_formed(svg_plot(s));
  }
  {
    PlotSpec s;  // many series: the palette cycles; tiny size is clamped
    s.width = 10;
    s.height = 10;
    for (int i = 0; i < 11; ++i) {
      s.series.push_back(PlotSeries{"s" + std::to_string(i), {{double(i), double(i * i)}}, {}, true});
    }
    expect_well_formed(svg_plot(s));
  }
}
