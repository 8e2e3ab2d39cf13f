// Result records and their writers (ARCHITECTURE §6, §7).
#include "eval/results.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "core/errors.h"
#include "core/files.h"

namespace ssr {
namespace {

// Shortest round-trip text of a double, independent of the C locale.
std::string number_text(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}
// An absent figure (an empty pixel set) is an empty CSV field.
std::string number_text(const std::optional<double>& v) { return v ? number_text(*v) : std::string(); }

std::string fixed_text(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}


nlohmann::json class_json(const ClassFigures& f, PixelClass c) {
  nlohmann::json j{{"pixels", f.pixels}, {"psnr", optional_json(f.psnr)}, {"psnr_reflection", optional_json(f.psnr_reflection)}};
  if (c == PixelClass::Traceable) {
    j["psnr_ideal"] = optional_json(f.psnr_ideal);
    j["psnr_reflection_ideal"] = optional_json(f.psnr_reflection_ideal);
    j["coverage"] = optional_json(f.coverage);
    j["correct_coverage"] = optional_json(f.correct_coverage);
    j["noise_floor_psnr"] = optional_json(f.noise_floor_psnr);
  } else {
    j["false_hit_rate"] = optional_json(f.false_hit_rate);
  }
  return j;
}

nlohmann::json technique_json(const TechniqueResult& r) {
  nlohmann::json params = params_json(r.params);
  nlohmann::json passes = nlohmann::json::array();
  for (const auto& p : r.passes) passes.push_back({{"name", p.name}, {"ms", p.ms}});
  return nlohmann::json{
      {"technique", r.technique},
      {"label", r.label.empty() ? r.technique : r.label},
      {"preset", r.preset},
      {"params", std::move(params)},
      {"ran_params", params_json(r.ran_params)},
      {"time_ms", {{"median", r.time_ms.median}, {"min", r.time_ms.min}, {"max", r.time_ms.max}}},
      {"passes", std::move(passes)},
      {"floor_ms", r.floor_ms},
      {"time_over_floor", time_over_floor(r)},
      {"error", error_json(r.error)},
      {"regions", breakdown_json(r.breakdown)},
      {"telemetry", telemetry_json(r.telemetry)},
      {"nonfinite", r.error.nonfinite},
      {"varies_per_frame", r.varies_per_frame},
  };
}

}  // namespace

nlohmann::json truth_noise_json(const std::optional<TruthNoise>& n) {
  if (!n) return nullptr;
  return {{"psnr", optional_json(n->psnr)}, {"psnr_traceable", optional_json(n->psnr_traceable)}};
}

nlohmann::json telemetry_json(const std::optional<IterationStats>& t) {
  if (!t) return nullptr;
  return nlohmann::json{
      {"rays", t->rays},
      {"iterations", {{"mean", t->mean}, {"p50", t->p50}, {"p95", t->p95}, {"max", t->max}}},
      {"idle_lanes", optional_json(t->idle_lanes)},
  };
}

namespace {


// The run without device and revision.
nlohmann::json run_json(const RunResults& run) {
  nlohmann::json results = nlohmann::json::array();
  for (const auto& r : run.results) results.push_back(technique_json(r));
  nlohmann::json j{
      {"size", {run.width, run.height}},
      {"scene", run.scene},
      {"results", std::move(results)},
      {"inherent_psnr", optional_json(run.inherent_psnr)},
      {"reference", params_json(run.reference_params)},
      {"frame", params_json(run.frame_settings)},
      {"inherent", {{"traceable", optional_json(run.inherent.traceable)},
                    {"missing", optional_json(run.inherent.missing)},
                    {"sky", optional_json(run.inherent.sky)}}},
      {"truth_noise", truth_noise_json(run.truth_noise)},
  };
  if (run.oracles)
    j["oracles"] = {{"pixels", run.oracles->pixels}, {"psnr", optional_json(run.oracles->psnr)},
                    {"within_1_255", optional_json(run.oracles->within_1_255)},
                    {"edge_pixels", run.oracles->edge_pixels},
                    {"psnr_off_edges", optional_json(run.oracles->psnr_off_edges)}};
  return j;
}

// RFC 4180: a field with a comma, quote, CR or LF is quoted, quotes doubled.
std::string csv_field(std::string_view s) {
  if (s.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(s);
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
  return out;
}

std::string params_text(const TechniqueResult& r) {
  std::string out;
  for (const auto& [key, value] : r.params) {
    if (!out.empty()) out += ';';
    out += key;
    out += '=';
    out += value;
  }
  return out;
}

// The last system error as text; errno may be 0 after a stream failure.
std::string errno_text(int e) {
  return e != 0 ? std::string(std::strerror(e)) : std::string("an input/output error occurred");
}

std::string pad_left(const std::string& s, std::size_t w) {
  return s.size() >= w ? s : std::string(w - s.size(), ' ') + s;
}
std::string pad_right(const std::string& s, std::size_t w) {
  return s.size() >= w ? s : s + std::string(w - s.size(), ' ');
}

}  // namespace

nlohmann::json params_json(const std::vector<std::pair<std::string, std::string>>& params) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [key, value] : params) j[key] = param_value_json(value);
  return j;
}

std::string db_text(const std::optional<double>& v) { return v ? fixed_text(*v, 2) : std::string("-"); }

nlohmann::json optional_json(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

nlohmann::json device_json(const DeviceInfo& d) {
  // How time_ms was taken (runner.h time_frames): bench JSON of before this method summed one
  // GL_TIME_ELAPSED query per pass and has no "timing" key.
  const char* timing = d.clock == "gpu" ? "technique span: two GL_TIMESTAMP queries, none between its passes"
                                        : "technique span: CPU clock around glFinish";
  return nlohmann::json{{"renderer", d.renderer}, {"version", d.version}, {"clock", d.clock}, {"timing", timing}};
}

nlohmann::json error_json(const ErrorMetrics& e) {
  return nlohmann::json{
      {"rmse", optional_json(e.rmse)},
      {"psnr", optional_json(e.psnr)},
      {"rmse_traceable", optional_json(e.rmse_traceable)},
      {"psnr_traceable", optional_json(e.psnr_traceable)},
      {"rmse_missing", optional_json(e.rmse_missing)},
      {"coverage", optional_json(e.coverage)},
      {"reflective", e.reflective},
      {"traceable", e.traceable},
      {"missing", e.missing},
      {"sky", e.sky},
  };
}

nlohmann::json breakdown_json(const Breakdown& b) {
  nlohmann::json regions = nlohmann::json::object();
  for (const RegionFigures& f : b.regions)
    regions[f.region.name()] = {
        {"pixels", f.pixels},
        {"handled", f.handled},
        {"handled_pixels", f.handled_pixels},
        {"traceable", class_json(f.traceable, PixelClass::Traceable)},
        {"missing", class_json(f.missing, PixelClass::Missing)},
        {"sky", class_json(f.sky, PixelClass::Sky)},
        {"hits", {{"correct", f.hits.correct}, {"false", f.hits.false_hits}, {"missed", f.hits.missed},
                  {"correct_miss", f.hits.correct_miss}}},
    };
  return regions;
}

TimeStats time_stats(std::vector<double> samples) {
  TimeStats t;
  if (samples.empty()) return t;
  std::sort(samples.begin(), samples.end());
  const std::size_t n = samples.size();
  t.min = samples.front();
  t.max = samples.back();
  t.median = (n % 2 == 1) ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
  return t;
}

double time_over_floor(const TechniqueResult& r) {
  if (!(r.floor_ms > 0.0)) return 0.0;
  return r.time_ms.median / r.floor_ms;
}

nlohmann::json param_value_json(const std::string& text) {
  if (text == "true") return true;
  if (text == "false") return false;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (!text.empty()) {
    long long i = 0;
    auto ri = std::from_chars(first, last, i);
    if (ri.ec == std::errc() && ri.ptr == last) return i;
    double d = 0;
    auto rd = std::from_chars(first, last, d);
    if (rd.ec == std::errc() && rd.ptr == last && std::isfinite(d)) return d;
  }
  return text;
}

nlohmann::json to_json(const DeviceInfo& device, const std::string& revision,
                       const RunResults& run) {
  nlohmann::json j = run_json(run);
  j["device"] = device_json(device);
  j["revision"] = revision;
  return j;
}

nlohmann::json bench_json(const DeviceInfo& device, const std::string& revision,
                          const std::vector<RunResults>& runs) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& run : runs) list.push_back(run_json(run));
  return nlohmann::json{
      {"device", device_json(device)}, {"revision", revision}, {"runs", std::move(list)}};
}

std::string results_csv(const std::vector<RunResults>& runs) {
  std::string out =
      "scene,width,height,technique,preset,params,time_median_ms,time_min_ms,time_max_ms,"
      "floor_ms,time_over_floor,rmse,psnr,rmse_traceable,psnr_traceable,rmse_missing,coverage,"
      "nonfinite\n";
  for (const auto& run : runs) {
    for (const auto& r : run.results) {
      const std::string fields[] = {
          csv_field(run.scene),
          std::to_string(run.width),
          std::to_string(run.height),
          csv_field(r.technique),
          csv_field(r.preset),
          csv_field(params_text(r)),
          number_text(r.time_ms.median),
          number_text(r.time_ms.min),
          number_text(r.time_ms.max),
          number_text(r.floor_ms),
          number_text(time_over_floor(r)),
          number_text(r.error.rmse),
          number_text(r.error.psnr),
          number_text(r.error.rmse_traceable),
          number_text(r.error.psnr_traceable),
          number_text(r.error.rmse_missing),
          number_text(r.error.coverage),
          std::to_string(r.error.nonfinite),
      };
      bool first = true;
      for (const auto& f : fields) {
        if (!first) out += ',';
        out += f;
        first = false;
      }
      out += '\n';
    }
  }
  return out;
}

std::string format_table(const std::vector<std::string>& header,
                         const std::vector<std::vector<std::string>>& rows) {
  for (const auto& row : rows)  // a row and its header are written side by side: keep them equal
    if (row.size() != header.size())
      throw std::logic_error("format_table: a row of " + std::to_string(row.size()) + " cells under " +
                             std::to_string(header.size()) + " columns.");
  std::vector<std::size_t> width(header.size());
  for (std::size_t c = 0; c < header.size(); ++c) {
    width[c] = header[c].size();
    for (const auto& row : rows) width[c] = std::max(width[c], row[c].size());
  }
  auto line = [&](const std::vector<std::string>& cells) {
    std::string s = pad_right(cells[0], width[0]);
    for (std::size_t c = 1; c < cells.size(); ++c) s += "  " + pad_left(cells[c], width[c]);
    return s + "\n";
  };
  std::string out = line(header);
  std::size_t total = width[0];
  for (std::size_t c = 1; c < width.size(); ++c) total += 2 + width[c];
  out += std::string(total, '-') + "\n";
  for (const auto& row : rows) out += line(row);
  return out;
}

namespace {

std::string percent_text(const std::optional<double>& v) {
  return v ? fixed_text(*v * 100.0, 1) + "%" : std::string("-");
}

// A region's traceable figure, or "n/a" where the technique does not handle any of it.
std::string region_cell(const TechniqueResult& r, const char* region, bool correct) {
  const RegionFigures* f = r.breakdown.find(region);
  if (!f) return "-";
  if (f->pixels > 0 && f->handled_pixels == 0) return "n/a";
  return correct ? percent_text(f->traceable.correct_coverage) : db_text(f->traceable.psnr_ideal);
}

// Claimed hits on missing and sky pixels over those pixels (the handled ones).
std::optional<double> false_hit_rate(const RegionFigures& f) {
  const std::size_t n = f.missing.pixels + f.sky.pixels;
  if (n == 0) return std::nullopt;
  const double claimed = f.missing.false_hit_rate.value_or(0) * static_cast<double>(f.missing.pixels) +
                         f.sky.false_hit_rate.value_or(0) * static_cast<double>(f.sky.pixels);
  return claimed / static_cast<double>(n);
}

// The table's false-hit cell: a share, or over fewer than 100 missing and sky pixels the count
// ("5 of 19"): a percentage of a handful read as a regression (cornell at 320x180: 26.3% against
// 10.5% were 5 pixels against 2).
std::string false_hits_cell(const RegionFigures& f) {
  const std::size_t n = f.missing.pixels + f.sky.pixels;
  const std::optional<double> rate = false_hit_rate(f);
  if (!rate || n >= 100) return percent_text(rate);
  return std::to_string(static_cast<std::size_t>(std::lround(*rate * static_cast<double>(n)))) + " of " + std::to_string(n);
}

// Traceable pixels claimed with the right colour over every traceable pixel, as `cover` next to
// it: a pixel the technique does not handle (ppr without fallback off its reflectors) is not
// correct. The breakdown's own correct_coverage is over the pixels handled.
std::optional<double> pooled_correct_coverage(const TechniqueResult& r) {
  const RegionFigures* all = r.breakdown.find("all");
  if (!all || r.error.traceable == 0) return std::nullopt;
  return static_cast<double>(all->traceable.correct_pixels) / static_cast<double>(r.error.traceable);
}

std::string row_name(const TechniqueResult& r) {
  if (!r.label.empty()) return r.label;
  return r.preset.empty() ? r.technique : r.technique + " [" + r.preset + "]";
}

}  // namespace

std::string results_table(const RunResults& run, const std::string& clock) {
  const std::vector<std::string> header = {
      "technique", "ms (" + clock + ")", "floor x", "PSNR dB", "trace dB", "cover", "correct",
      "planar dB", "planar ok", "other dB", "other ok", "false hits", "nonfinite"};
  std::vector<std::vector<std::string>> rows;
  for (const auto& r : run.results) {
    const double tof = time_over_floor(r);
    const RegionFigures* all = r.breakdown.find("all");
    rows.push_back({
        row_name(r),
        fixed_text(r.time_ms.median, 2),
        tof > 0.0 ? fixed_text(tof, 2) : std::string("-"),
        db_text(r.error.psnr),
        db_text(r.error.psnr_traceable),
        percent_text(r.error.coverage),
        percent_text(pooled_correct_coverage(r)),
        region_cell(r, "planar", false),
        region_cell(r, "planar", true),
        region_cell(r, "other", false),
        region_cell(r, "other", true),
        all ? false_hits_cell(*all) : std::string("-"),
        std::to_string(r.error.nonfinite),
    });
  }
  std::string out = run.scene + " " + std::to_string(run.width) + "x" +
                    std::to_string(run.height) + ", inherent PSNR " +
                    db_text(run.inherent_psnr) + " dB (traceable " + db_text(run.inherent.traceable) +
                    ", missing " + db_text(run.inherent.missing) + ", sky " + db_text(run.inherent.sky) + ")" +
                    (run.truth_noise ? "; truth noise floor " + db_text(run.truth_noise->psnr) + " dB (traceable " +
                                           db_text(run.truth_noise->psnr_traceable) + ")"
                                     : std::string()) +
                    "\n";
  out += format_table(header, rows);
  out += "trace dB: vs the screen-space ideal on traceable pixels; correct/ok: traceable pixels hit "
         "with the right colour; n/a: not handled.\n";
  std::string varying;
  for (const TechniqueResult& r : run.results)
    if (r.varies_per_frame) varying += (varying.empty() ? "" : ", ") + row_name(r);
  if (!varying.empty())
    out += "first frame, before any history: " + varying + " accumulate over frames (ssrlab sequence scores them there).\n";
  if (run.truth_noise)
    out += "truth noise floor: what the noise-free truth would score against this sampled one; a figure near it "
           "is the truth's noise, not the technique's error (raise reference.samples).\n";
  if (run.oracles && run.oracles->pixels > 0)
    out += "oracles (planar vs reference, mirror reflector pixels): " + db_text(run.oracles->psnr) +
           " dB, " + percent_text(run.oracles->within_1_255) + " within 1/255, " +
           db_text(run.oracles->psnr_off_edges) + " dB off " + std::to_string(run.oracles->edge_pixels) +
           " edge pixels (" + std::to_string(run.oracles->pixels) + " pixels)\n";
  return out;
}

std::string breakdown_table(const RunResults& run, const std::vector<std::string>& regions) {
  const std::vector<std::string> header = {
      "region", "pixels", "trace px", "vs truth", "vs ideal", "refl dB", "refl ideal", "cover",
      "correct", "noise floor", "missing px", "vs truth", "false", "sky px", "vs truth", "false"};
  std::string out;
  for (const auto& r : run.results) {
    std::vector<std::vector<std::string>> rows;
    for (const RegionFigures& f : r.breakdown.regions) {
      if (f.pixels == 0) continue;
      if (!regions.empty() && std::find(regions.begin(), regions.end(), f.region.name()) == regions.end()) continue;
      std::string name = f.region.name();
      if (f.handled_pixels == 0) {
        rows.push_back({name, std::to_string(f.pixels), "not handled", "", "", "", "", "", "", "", "", "", "", "", "", ""});
        continue;
      }
      if (!f.handled) name += " (" + std::to_string(f.handled_pixels) + " handled)";
      rows.push_back({name, std::to_string(f.pixels), std::to_string(f.traceable.pixels),
                      db_text(f.traceable.psnr), db_text(f.traceable.psnr_ideal),
                      db_text(f.traceable.psnr_reflection), db_text(f.traceable.psnr_reflection_ideal),
                      percent_text(f.traceable.coverage), percent_text(f.traceable.correct_coverage),
                      db_text(f.traceable.noise_floor_psnr), std::to_string(f.missing.pixels),
                      db_text(f.missing.psnr), percent_text(f.missing.false_hit_rate),
                      std::to_string(f.sky.pixels), db_text(f.sky.psnr), percent_text(f.sky.false_hit_rate)});
    }
    out += row_name(r) + "\n" + format_table(header, rows) + "\n";
  }
  return out;
}

void write_text_file_atomic(const std::filesystem::path& file, const std::string& text) {
  const std::filesystem::path path = files::write_target(file);
  const std::filesystem::path tmp = files::temp_path_beside(path);
  auto fail = [&](const std::string& why) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw RuntimeError("Could not write '" + path.string() + "': " + why + ".");
  };
  {
    errno = 0;
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) fail(errno_text(errno));
    f.write(text.data(), static_cast<std::streamsize>(text.size()));
    f.flush();
    if (!f) fail(errno_text(errno));
    f.close();
    if (!f) fail(errno_text(errno));
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) fail(ec.message());
}

}  // namespace ssr
