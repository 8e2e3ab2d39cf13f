// Result records and writers: time statistics, results/bench JSON (ARCHITECTURE §7), CSV, table,
// atomic text files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "core/errors.h"
#include "eval/results.h"

using namespace ssr;

namespace {

RunResults sample_run() {
  RunResults run;
  run.scene = "cornell";
  run.width = 640;
  run.height = 360;
  run.inherent_psnr = 31.5;

  TechniqueResult a;
  a.technique = "linear";
  a.params = {{"linear.max_steps", "64"},
              {"linear.thickness", "0.05"},
              {"linear.jitter", "true"},
              {"linear.refine", "false"},
              {"linear.mode", "view, \"space\""}};
  a.time_ms = {1.5, 1.25, 2.0};
  a.passes = {{"gbuffer", 0.5}, {"lit", 0.25}, {"linear", 1.5}};
  a.floor_ms = 0.5;
  a.error.rmse = 0.05;
  a.error.psnr = 26.0;
  a.error.rmse_traceable = 0.02;
  a.error.psnr_traceable = 33.98;
  a.error.rmse_missing = 0.2;
  a.error.coverage = 0.875;
  a.error.reflective = 1000;
  a.error.traceable = 800;
  a.error.missing = 150;
  a.error.sky = 50;

  TechniqueResult b;
  b.technique = "none";
  b.preset = "fast";
  b.time_ms = {0.0, 0.0, 0.0};
  b.floor_ms = 0.0;
  b.error.nonfinite = 3;

  run.results = {a, b};
  return run;
}

DeviceInfo sample_device() { return {"llvmpipe (LLVM 15.0.6, 256 bits)", "4.6 (Core Profile) Mesa", "cpu"}; }

// RFC 4180 parser for the test: records of fields.
std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> row;
  std::string field;
  bool quoted = false, any = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    any = true;
    if (quoted) {
      if (c == '"') {
        if (i + 1 < text.size() && text[i + 1] == '"') {
          field += '"';
          ++i;
        } else {
          quoted = false;
        }
      } else {
        field += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      row.push_back(field);
      field.clear();
    } else if (c == '\n') {
      row.push_back(field);
      field.clear();
      rows.push_back(row);
      row.clear();
      any = false;
    } else {
      field += c;
    }
  }
  if (any) {
    row.push_back(field);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

TEST(Results, TimeStats) {
  const TimeStats odd = time_stats({5.0, 1.0, 3.0});
  EXPECT_EQ(odd.median, 3.0);
  EXPECT_EQ(odd.min, 1.0);
  EXPECT_EQ(odd.max, 5.0);

  const TimeStats even = time_stats({4.0, 1.0, 3.0, 10.0});
  EXPECT_EQ(even.median, 3.5);
  EXPECT_EQ(even.min, 1.0);
  EXPECT_EQ(even.max, 10.0);

  const TimeStats one = time_stats({2.5});
  EXPECT_EQ(one.median, 2.5);
  EXPECT_EQ(one.min, 2.5);
  EXPECT_EQ(one.max, 2.5);

  const TimeStats none = time_stats({});
  EXPECT_EQ(none.median, 0.0);
  EXPECT_EQ(none.min, 0.0);
  EXPECT_EQ(none.max, 0.0);
}

TEST(Results, JsonHasEveryFieldOfTheContract) {
  const auto j = to_json(sample_device(), "abc1234", sample_run());
  for (const char* k : {"device", "size", "scene", "revision", "results", "inherent_psnr"}) {
    EXPECT_TRUE(j.contains(k)) << k;
  }
  for (const char* k : {"renderer", "version", "clock"}) EXPECT_TRUE(j["device"].contains(k)) << k;
  EXPECT_EQ(j["device"]["clock"], "cpu");
  EXPECT_EQ(j["size"], nlohmann::json::array({640, 360}));
  EXPECT_EQ(j["scene"], "cornell");
  EXPECT_EQ(j["revision"], "abc1234");
  EXPECT_DOUBLE_EQ(j["inherent_psnr"].get<double>(), 31.5);
  ASSERT_EQ(j["results"].size(), 2u);
  for (const auto& r : j["results"]) {
    for (const char* k : {"technique", "preset", "params", "time_ms", "passes", "floor_ms",
                          "time_over_floor", "error", "nonfinite", "ran_params", "varies_per_frame"}) {
      EXPECT_TRUE(r.contains(k)) << k;
    }
    for (const char* k : {"median", "min", "max"}) EXPECT_TRUE(r["time_ms"].contains(k)) << k;
    for (const char* k : {"rmse", "psnr", "rmse_traceable", "psnr_traceable", "rmse_missing",
                          "coverage", "reflective", "traceable", "missing", "sky"}) {
      EXPECT_TRUE(r["error"].contains(k)) << k;
    }
    EXPECT_TRUE(r["params"].is_object());
    EXPECT_TRUE(r["passes"].is_array());
  }
  const auto& a = j["results"][0];
  EXPECT_EQ(a["technique"], "linear");
  EXPECT_EQ(a["preset"], "");
  EXPECT_DOUBLE_EQ(a["time_ms"]["median"].get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(a["time_ms"]["min"].get<double>(), 1.25);
  EXPECT_DOUBLE_EQ(a["time_ms"]["max"].get<double>(), 2.0);
  ASSERT_EQ(a["passes"].size(), 3u);
  EXPECT_EQ(a["passes"][2]["name"], "linear");
  EXPECT_DOUBLE_EQ(a["passes"][2]["ms"].get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(a["floor_ms"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(a["time_over_floor"].get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(a["error"]["coverage"].get<double>(), 0.875);
  EXPECT_EQ(a["error"]["traceable"], 800);
  EXPECT_EQ(a["nonfinite"], 0);
  for (const char* k : {"rmse", "psnr", "rmse_traceable", "psnr_traceable", "rmse_missing", "coverage"})
    EXPECT_TRUE(a["error"][k].is_number()) << k;
  const auto& b = j["results"][1];
  // b has no reflective pixel: no figure, null (never 100 dB or 0%), the counts 0.
  for (const char* k : {"rmse", "psnr", "rmse_traceable", "psnr_traceable", "rmse_missing", "coverage"})
    EXPECT_TRUE(b["error"][k].is_null()) << k;
  EXPECT_EQ(b["error"]["reflective"], 0);
  EXPECT_EQ(b["preset"], "fast");
  EXPECT_EQ(b["time_over_floor"], 0.0);  // floor 0
  EXPECT_EQ(b["nonfinite"], 3);

  // Round trip.
  const auto back = nlohmann::json::parse(j.dump());
  EXPECT_EQ(back, j);
  const auto back2 = nlohmann::json::parse(j.dump(2));
  EXPECT_EQ(back2, j);
}

TEST(Results, ParamsAreTyped) {
  const auto j = to_json(sample_device(), "r", sample_run());
  const auto& p = j["results"][0]["params"];
  ASSERT_TRUE(p.contains("linear.max_steps"));
  EXPECT_TRUE(p["linear.max_steps"].is_number_integer());
  EXPECT_EQ(p["linear.max_steps"], 64);
  EXPECT_TRUE(p["linear.thickness"].is_number_float());
  EXPECT_DOUBLE_EQ(p["linear.thickness"].get<double>(), 0.05);
  EXPECT_TRUE(p["linear.jitter"].is_boolean());
  EXPECT_EQ(p["linear.jitter"], true);
  EXPECT_EQ(p["linear.refine"], false);
  EXPECT_TRUE(p["linear.mode"].is_string());
  EXPECT_EQ(p["linear.mode"], "view, \"space\"");

  EXPECT_EQ(param_value_json("-3"), -3);
  EXPECT_TRUE(param_value_json("1e-3").is_number_float());
  EXPECT_TRUE(param_value_json("nan").is_string());
  EXPECT_TRUE(param_value_json("inf").is_string());
  EXPECT_TRUE(param_value_json("12abc").is_string());
  EXPECT_TRUE(param_value_json("").is_string());
  EXPECT_TRUE(param_value_json(" 1").is_string());
  EXPECT_TRUE(param_value_json("True").is_string());
  EXPECT_EQ(j["results"][1]["params"], nlohmann::json::object());
}

TEST(Results, BenchJson) {
  RunResults r2 = sample_run();
  r2.width = 1280;
  r2.height = 720;
  const auto j = bench_json(sample_device(), "abc1234", {sample_run(), r2});
  EXPECT_EQ(j["revision"], "abc1234");
  EXPECT_EQ(j["device"]["renderer"], "llvmpipe (LLVM 15.0.6, 256 bits)");
  ASSERT_EQ(j["runs"].size(), 2u);
  const auto single = to_json(sample_device(), "abc1234", sample_run());
  for (const auto& run : j["runs"]) {
    EXPECT_FALSE(run.contains("device"));
    EXPECT_FALSE(run.contains("revision"));
    for (const char* k : {"size", "scene", "results", "inherent_psnr"}) {
      EXPECT_TRUE(run.contains(k)) << k;
    }
  }
  auto first = j["runs"][0];
  first["device"] = single["device"];
  first["revision"] = single["revision"];
  EXPECT_EQ(first, single);
  EXPECT_EQ(j["runs"][1]["size"], nlohmann::json::array({1280, 720}));
  EXPECT_EQ(nlohmann::json::parse(j.dump()), j);
}

TEST(Results, Csv) {
  RunResults run = sample_run();
  run.scene = "my,\"scene\"";
  const std::string csv = results_csv({run, sample_run()});
  const std::string header =
      "scene,width,height,technique,preset,params,time_median_ms,time_min_ms,time_max_ms,"
      "floor_ms,time_over_floor,rmse,psnr,rmse_traceable,psnr_traceable,rmse_missing,coverage,"
      "nonfinite";
  EXPECT_EQ(csv.substr(0, csv.find('\n')), header);

  const auto rows = parse_csv(csv);
  ASSERT_EQ(rows.size(), 5u);  // header + 2 runs x 2 results
  for (const auto& row : rows) EXPECT_EQ(row.size(), 18u);
  EXPECT_EQ(rows[1][0], "my,\"scene\"");
  EXPECT_EQ(rows[1][1], "640");
  EXPECT_EQ(rows[1][2], "360");
  EXPECT_EQ(rows[1][3], "linear");
  EXPECT_EQ(rows[1][4], "");
  EXPECT_EQ(rows[1][5],
            "linear.max_steps=64;linear.thickness=0.05;linear.jitter=true;linear.refine=false;"
            "linear.mode=view, \"space\"");
  EXPECT_EQ(std::stod(rows[1][6]), 1.5);
  EXPECT_EQ(std::stod(rows[1][10]), 3.0);
  EXPECT_EQ(std::stod(rows[1][11]), 0.05);
  EXPECT_EQ(std::stod(rows[1][16]), 0.875);
  EXPECT_EQ(rows[2][3], "none");
  EXPECT_EQ(rows[2][4], "fast");
  EXPECT_EQ(rows[2][17], "3");
  for (int k = 11; k <= 16; ++k) EXPECT_EQ(rows[2][static_cast<std::size_t>(k)], "") << k;  // no figure
  EXPECT_EQ(rows[3][0], "cornell");

  // Only the header when there is nothing.
  EXPECT_EQ(results_csv({}), header + "\n");
}

TEST(Results, Table) {
  const std::string t = results_table(sample_run(), "gpu");
  EXPECT_NE(t.find("linear"), std::string::npos);
  EXPECT_NE(t.find("none [fast]"), std::string::npos);
  EXPECT_NE(t.find("ms (gpu)"), std::string::npos);
  EXPECT_NE(t.find("1.50"), std::string::npos);     // ms, 2 decimals
  EXPECT_NE(t.find("3.00"), std::string::npos);     // floor x
  EXPECT_NE(t.find("26.00"), std::string::npos);    // PSNR
  EXPECT_NE(t.find("33.98"), std::string::npos);    // PSNR traceable
  EXPECT_NE(t.find("87.5%"), std::string::npos);    // coverage
  EXPECT_NE(t.find("cornell"), std::string::npos);
  // Fixed width: every table line (header, rule, rows) has the same length.
  std::istringstream in(t);
  std::string line;
  std::getline(in, line);  // title
  std::size_t width = 0;
  while (std::getline(in, line)) {
    if (width == 0) width = line.size();
    EXPECT_EQ(line.size(), width) << line;
  }
  EXPECT_GT(width, 0u);
}

// "cover" and "correct" sit side by side over the same pixels, every traceable one: a technique
// that handles part of the frame (ppr without fallback) is not correct where it does nothing,
// although its breakdown's correct_coverage is over the pixels it handles.
TEST(Results, TableCorrectIsPooledAsCover) {
  RunResults run = sample_run();
  RegionFigures all;
  all.region = {RegionKind::All, 0};
  all.pixels = 1000;
  all.handled = false;
  all.handled_pixels = 500;
  all.traceable.pixels = 400;  // handled traceable pixels, of the run's 800
  all.traceable.correct_pixels = 300;
  all.traceable.correct_coverage = 0.75;
  run.results[0].breakdown.regions = {all};
  const std::string t = results_table(run, "gpu");
  EXPECT_NE(t.find("37.5%"), std::string::npos) << t;  // 300 of 800
  EXPECT_EQ(t.find("75.0%"), std::string::npos) << t;
  // The row without reflective pixels shows "-" for its figures, not 100 dB.
  EXPECT_EQ(t.find("100.00"), std::string::npos) << t;
}

// A false-hit share of a handful of pixels reads as a regression: under 100 missing and sky
// pixels the table gives the count.
TEST(Results, TableFalseHitsOfFewPixelsAreCounted) {
  RunResults run = sample_run();
  RegionFigures all;
  all.region = {RegionKind::All, 0};
  all.pixels = 1000;
  all.handled_pixels = 1000;
  all.missing.pixels = 19;
  all.missing.false_hit_rate = 2.0 / 19.0;
  run.results[0].breakdown.regions = {all};
  EXPECT_NE(results_table(run, "gpu").find("2 of 19"), std::string::npos) << results_table(run, "gpu");
  all.sky.pixels = 181;  // 200 pixels in all: a share again
  all.sky.false_hit_rate = 0.0;
  run.results[0].breakdown.regions = {all};
  EXPECT_NE(results_table(run, "gpu").find("1.0%"), std::string::npos) << results_table(run, "gpu");
}

// A technique whose image changes frame to frame is scored on its first frame: the table says so
// and names it (a stochastic row read as its converged figure).
TEST(Results, TableSaysWhichRowsAreAFirstFrame) {
  RunResults run = sample_run();
  EXPECT_EQ(results_table(run, "gpu").find("first frame"), std::string::npos);
  run.results[0].varies_per_frame = true;
  const std::string t = results_table(run, "gpu");
  EXPECT_NE(t.find("first frame, before any history: linear accumulate"), std::string::npos) << t;
}

TEST(Results, WriteTextFileAtomic) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("ssrlab_results_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto path = dir / "out.json";
  write_text_file_atomic(path, "hello\n");
  write_text_file_atomic(path, "{\"a\":1}\n");  // replaces
  {
    std::ifstream f(path, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    EXPECT_EQ(ss.str(), "{\"a\":1}\n");
  }
  // Nothing but the target is left behind.
  std::size_t entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    (void)e;
    ++entries;
  }
  EXPECT_EQ(entries, 1u);

  // A missing directory: RuntimeError, and no file appears.
  const auto bad = dir / "no_such_dir" / "out.csv";
  EXPECT_THROW(write_text_file_atomic(bad, "x"), RuntimeError);
  EXPECT_FALSE(std::filesystem::exists(bad));

  // Renaming onto a directory fails: the temporary file is removed.
  const auto subdir = dir / "a_directory";
  std::filesystem::create_directories(subdir / "child");
  EXPECT_THROW(write_text_file_atomic(subdir, "x"), RuntimeError);
  entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    (void)e;
    ++entries;
  }
  EXPECT_EQ(entries, 2u);  // out.json and a_directory

  std::filesystem::remove_all(dir);
}
