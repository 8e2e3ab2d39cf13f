// A small, dependency-free SVG line/scatter plot writer.
#include "eval/svg_plot.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>

namespace ssr {
namespace {

// Okabe-Ito, reordered so that the first colours are the most distinct on white (yellow last).
constexpr std::array<const char*, 8> kPalette = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                                 "#E69F00", "#56B4E9", "#000000", "#F0E442"};

// Values beyond this magnitude are not plotted: it keeps every range computation finite.
constexpr double kMaxMagnitude = 1e300;

// A coordinate, locale-independent, 2 decimals. Never "nan"/"inf".
std::string num(double v) {
  if (!std::isfinite(v)) v = 0.0;
  char buf[512];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 2);
  if (r.ec != std::errc()) return "0";
  std::string s(buf, r.ptr);
  if (s == "-0.00") s = "0.00";
  return s;
}

std::string fixed(double v, int decimals) {
  char buf[512];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  if (r.ec != std::errc()) return "0";
  std::string s(buf, r.ptr);
  // "-0", "-0.0"...: drop the sign of a zero.
  if (s.front() == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

std::string general(double v, int digits) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, digits);
  if (r.ec != std::errc()) return "0";
  return std::string(buf, r.ptr);
}

struct Tick {
  double pos;         // in axis space (log10 of the value on a log axis)
  std::string label;  // empty: a minor tick (grid line only)
};

struct Axis {
  bool log = false;
  double lo = 0, hi = 1;  // axis space
  std::vector<Tick> ticks;

  // 0 at lo, 1 at hi.
  double frac(double value) const {
    const double a = log ? std::log10(value) : value;
    return (a - lo) / (hi - lo);
  }
};

bool usable(double v, bool log) {
  if (!std::isfinite(v) || std::fabs(v) > kMaxMagnitude) return false;
  return !log || v > 0.0;
}

double nice_step(double raw) {
  const double e = std::floor(std::log10(raw));
  const double p = std::pow(10.0, e);
  const double f = raw / p;
  const double nf = f <= 1.0 ? 1.0 : f <= 2.0 ? 2.0 : f <= 5.0 ? 5.0 : 10.0;
  return nf * p;
}

Axis linear_axis(const std::vector<double>& values) {
  Axis ax;
  double mn = 0.0, mx = 1.0;
  if (!values.empty()) {
    const auto [a, b] = std::minmax_element(values.begin(), values.end());
    mn = *a;
    mx = *b;
  }
  if (mx - mn <= std::max(std::fabs(mn), std::fabs(mx)) * 1e-12) {  // a single value: pad
    const double pad = mn == 0.0 ? 1.0 : std::fabs(mn) * 0.1;
    mn -= pad;
    mx += pad;
  }
  const double step = nice_step((mx - mn) / 5.0);
  ax.lo = std::floor(mn / step) * step;
  ax.hi = std::ceil(mx / step) * step;
  if (!(ax.hi > ax.lo)) {  // rounding at the edge of precision: keep the plain range
    ax.lo = mn;
    ax.hi = mx;
  }
  const long long n = std::clamp<long long>(std::llround((ax.hi - ax.lo) / step), 1, 100);

  const double maxabs = std::max(std::fabs(ax.lo), std::fabs(ax.hi));
  const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
  const bool plain = decimals <= 6 && maxabs < 1e7;
  const int digits =
      std::clamp(static_cast<int>(std::ceil(std::log10(maxabs / step))) + 1, 1, 15);
  for (long long i = 0; i <= n; ++i) {
    double v = ax.lo + static_cast<double>(i) * step;
    if (std::fabs(v) < step * 1e-9) v = 0.0;
    if (v > ax.hi + step * 1e-9) break;
    ax.ticks.push_back({v, plain ? fixed(v, decimals) : general(v, digits)});
  }
  return ax;
}

std::string decade_label(int d) {
  if (d >= -4 && d <= 6) return fixed(std::pow(10.0, d), std::max(0, -d));
  return "1e" + std::to_string(d);
}

Axis log_axis(const std::vector<double>& values) {
  Axis ax;
  ax.log = true;
  int dlo = 0, dhi = 1;
  if (!values.empty()) {
    const auto [a, b] = std::minmax_element(values.begin(), values.end());
    dlo = static_cast<int>(std::floor(std::log10(*a)));
    dhi = static_cast<int>(std::ceil(std::log10(*b)));
    if (dlo == dhi) {
      --dlo;
      ++dhi;
    }
  }
  ax.lo = dlo;
  ax.hi = dhi;
  const int span = dhi - dlo;
  const int every = std::max(1, (span + 7) / 8);  // at most ~9 labelled decades
  for (int d = dlo; d <= dhi; ++d) {
    if ((d - dlo) % every == 0) ax.ticks.push_back({static_cast<double>(d), decade_label(d)});
    if (span <= 6 && d < dhi) {
      ax.ticks.push_back({d + std::log10(2.0), ""});
      ax.ticks.push_back({d + std::log10(5.0), ""});
    }
  }
  return ax;
}

std::string marker(std::size_t series, double x, double y, const char* colour) {
  const std::string fill = std::string(" fill=\"") + colour + "\"";
  switch (series % 4) {
    case 0:
      return "<circle cx=\"" + num(x) + "\" cy=\"" + num(y) + "\" r=\"3.5\"" + fill + "/>";
    case 1:
      return "<rect x=\"" + num(x - 3.2) + "\" y=\"" + num(y - 3.2) +
             "\" width=\"6.4\" height=\"6.4\"" + fill + "/>";
    case 2:
      return "<polygon points=\"" + num(x) + "," + num(y - 4.5) + " " + num(x + 4.5) + "," +
             num(y) + " " + num(x) + "," + num(y + 4.5) + " " + num(x - 4.5) + "," + num(y) +
             "\"" + fill + "/>";
    default:
      return "<polygon points=\"" + num(x) + "," + num(y - 4.5) + " " + num(x + 4.2) + "," +
             num(y + 3.2) + " " + num(x - 4.2) + "," + num(y + 3.2) + "\"" + fill + "/>";
  }
}

}  // namespace

std::string xml_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        // Control characters other than tab/newline are not allowed in XML 1.0.
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') {
          out += ' ';
        } else {
          out += c;
        }
    }
  }
  return out;
}

std::string svg_plot(const PlotSpec& spec) {
  const int W = std::max(spec.width, 240);
  const int H = std::max(spec.height, 180);

  // Usable points of every series.
  std::vector<double> xs, ys;
  for (const auto& s : spec.series) {
    for (const auto& [x, y] : s.points) {
      if (usable(x, spec.log_x) && usable(y, spec.log_y)) {
        xs.push_back(x);
        ys.push_back(y);
      }
    }
  }
  const Axis ax = spec.log_x ? log_axis(xs) : linear_axis(xs);
  const Axis ay = spec.log_y ? log_axis(ys) : linear_axis(ys);

  // Layout: title on top, tick labels and axis labels left/bottom, legend on the right.
  std::size_t longest = 0;
  for (const auto& s : spec.series) longest = std::max(longest, s.name.size());
  const double legend_w =
      spec.series.empty() ? 0.0 : std::min(48.0 + 7.5 * static_cast<double>(longest), W / 3.0);
  const double left = 78, right = 16 + legend_w, top = spec.title.empty() ? 20 : 42,
               bottom = 56;
  const double x0 = left, x1 = W - right, y0 = top, y1 = H - bottom;
  auto px = [&](double v) { return x0 + ax.frac(v) * (x1 - x0); };
  auto py = [&](double v) { return y1 - ay.frac(v) * (y1 - y0); };
  auto px_axis = [&](double a) { return x0 + (a - ax.lo) / (ax.hi - ax.lo) * (x1 - x0); };
  auto py_axis = [&](double a) { return y1 - (a - ay.lo) / (ay.hi - ay.lo) * (y1 - y0); };

  std::string o;
  o += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(W) +
       "\" height=\"" + std::to_string(H) + "\" viewBox=\"0 0 " + std::to_string(W) + " " +
       std::to_string(H) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  o += "<rect x=\"0\" y=\"0\" width=\"" + std::to_string(W) + "\" height=\"" +
       std::to_string(H) + "\" fill=\"#ffffff\"/>\n";
  if (!spec.title.empty()) {
    o += "<text class=\"title\" x=\"" + num((x0 + x1) / 2) +
         "\" y=\"26\" text-anchor=\"middle\" font-size=\"15\" font-weight=\"bold\">" +
         xml_escape(spec.title) + "</text>\n";
  }

  // Grid and ticks.
  o += "<g class=\"grid\">\n";
  for (const auto& t : ax.ticks) {
    const double x = px_axis(t.pos);
    o += "<line x1=\"" + num(x) + "\" y1=\"" + num(y0) + "\" x2=\"" + num(x) + "\" y2=\"" +
         num(y1) + "\" stroke=\"" + (t.label.empty() ? "#f0f0f0" : "#dddddd") +
         "\" stroke-width=\"1\"/>\n";
  }
  for (const auto& t : ay.ticks) {
    const double y = py_axis(t.pos);
    o += "<line x1=\"" + num(x0) + "\" y1=\"" + num(y) + "\" x2=\"" + num(x1) + "\" y2=\"" +
         num(y) + "\" stroke=\"" + (t.label.empty() ? "#f0f0f0" : "#dddddd") +
         "\" stroke-width=\"1\"/>\n";
  }
  o += "</g>\n";
  o += "<rect x=\"" + num(x0) + "\" y=\"" + num(y0) + "\" width=\"" + num(x1 - x0) +
       "\" height=\"" + num(y1 - y0) + "\" fill=\"none\" stroke=\"#333333\" stroke-width=\"1\"/>\n";
  for (const auto& t : ax.ticks) {
    if (t.label.empty()) continue;
    const double x = px_axis(t.pos);
    o += "<line x1=\"" + num(x) + "\" y1=\"" + num(y1) + "\" x2=\"" + num(x) + "\" y2=\"" +
         num(y1 + 5) + "\" stroke=\"#333333\"/>\n";
    o += "<text class=\"tick-x\" x=\"" + num(x) + "\" y=\"" + num(y1 + 18) +
         "\" text-anchor=\"middle\">" + xml_escape(t.label) + "</text>\n";
  }
  for (const auto& t : ay.ticks) {
    if (t.label.empty()) continue;
    const double y = py_axis(t.pos);
    o += "<line x1=\"" + num(x0 - 5) + "\" y1=\"" + num(y) + "\" x2=\"" + num(x0) + "\" y2=\"" +
         num(y) + "\" stroke=\"#333333\"/>\n";
    o += "<text class=\"tick-y\" x=\"" + num(x0 - 8) + "\" y=\"" + num(y + 4) +
         "\" text-anchor=\"end\">" + xml_escape(t.label) + "</text>\n";
  }
  if (!spec.x_label.empty()) {
    o += "<text class=\"x-label\" x=\"" + num((x0 + x1) / 2) + "\" y=\"" + num(H - 14.0) +
         "\" text-anchor=\"middle\">" + xml_escape(spec.x_label) + "</text>\n";
  }
  if (!spec.y_label.empty()) {
    const double cy = (y0 + y1) / 2;
    o += "<text class=\"y-label\" x=\"18\" y=\"" + num(cy) +
         "\" text-anchor=\"middle\" transform=\"rotate(-90 18 " + num(cy) + ")\">" +
         xml_escape(spec.y_label) + "</text>\n";
  }

  // Data.
  for (std::size_t si = 0; si < spec.series.size(); ++si) {
    const PlotSeries& s = spec.series[si];
    const char* colour = kPalette[si % kPalette.size()];
    o += "<g class=\"series\">\n";
    if (s.lines) {
      std::vector<std::string> run;  // consecutive usable points; a skipped point breaks the line
      auto flush = [&] {
        if (run.size() >= 2) {
          std::string pts;
          for (const auto& p : run) pts += (pts.empty() ? "" : " ") + p;
          o += "<polyline points=\"" + pts + "\" fill=\"none\" stroke=\"" + colour +
               "\" stroke-width=\"1.75\" stroke-linejoin=\"round\"/>\n";
        }
        run.clear();
      };
      for (const auto& [x, y] : s.points) {
        if (usable(x, spec.log_x) && usable(y, spec.log_y)) {
          run.push_back(num(px(x)) + "," + num(py(y)));
        } else {
          flush();
        }
      }
      flush();
    }
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const auto [x, y] = s.points[i];
      if (!usable(x, spec.log_x) || !usable(y, spec.log_y)) continue;
      o += marker(si, px(x), py(y), colour) + "\n";
      if (i < s.labels.size() && !s.labels[i].empty()) {
        o += "<text class=\"point-label\" x=\"" + num(px(x) + 5) + "\" y=\"" + num(py(y) - 5) +
             "\" font-size=\"9\" fill=\"#444444\">" + xml_escape(s.labels[i]) + "</text>\n";
      }
    }
    o += "</g>\n";
  }

  // Legend.
  if (!spec.series.empty()) {
    const double lx = x1 + 14;
    o += "<g class=\"legend\">\n";
    for (std::size_t si = 0; si < spec.series.size(); ++si) {
      const PlotSeries& s = spec.series[si];
      const char* colour = kPalette[si % kPalette.size()];
      const double ly = y0 + 10 + 20.0 * static_cast<double>(si);
      if (s.lines) {
        o += "<line x1=\"" + num(lx) + "\" y1=\"" + num(ly) + "\" x2=\"" + num(lx + 22) +
             "\" y2=\"" + num(ly) + "\" stroke=\"" + colour + "\" stroke-width=\"1.75\"/>\n";
      }
      o += marker(si, lx + 11, ly, colour) + "\n";
      o += "<text class=\"legend-label\" x=\"" + num(lx + 28) + "\" y=\"" + num(ly + 4) + "\">" +
           xml_escape(s.name) + "</text>\n";
    }
    o += "</g>\n";
  }
  o += "</svg>\n";
  return o;
}

}  // namespace ssr
