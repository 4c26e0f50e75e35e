// The report's two charts. Both share one frame (plot area, axes, ticks, labels) and write their
// numbers through svg_writing.hpp, so the text is the same in every locale. Colours match the
// page's status colours (campaign_report_html.cpp).
#include "fuzz/campaign/campaign_report_svg.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "physics/map/svg_writing.hpp"

namespace scenfuzz {

namespace {

// Status colours, as the page's badges.
constexpr const char* kNewColour = "#c62828";
constexpr const char* kRegressedColour = "#ef6c00";
constexpr const char* kStillFailingColour = "#8d6e63";
constexpr const char* kFixedColour = "#2e7d32";
constexpr const char* kAxisColour = "#455a64";
constexpr const char* kGridColour = "#e3e7ea";

// Where the plot area is inside the picture, and how values map onto it.
struct Frame {
  double width = 640, height = 280;
  double left = 72, right = 20, top = 30, bottom = 52;
  double x_low = 0, x_high = 1, y_low = 0, y_high = 1;

  double plot_width() const { return width - left - right; }
  double plot_height() const { return height - top - bottom; }
  double x(double value) const { return left + (value - x_low) / (x_high - x_low) * plot_width(); }
  // Infinities are drawn at the edges of the plot area.
  double y(double value) const {
    const double clamped = std::clamp(value, y_low, y_high);
    return top + (y_high - clamped) / (y_high - y_low) * plot_height();
  }
};

std::string number(double value) { return number_text(value, 3); }

// A tick's text: large counts without a fraction, small values with their digits.
std::string tick_text(double value) {
  if (std::fabs(value) >= 1e6) return number_text(value / 1e6, 2) + "M";
  if (std::fabs(value) >= 1e4) return number_text(value / 1e3, 1) + "k";
  return number_text(value, 3);
}

void append_line(std::string& svg, double x1, double y1, double x2, double y2,
                 const std::string& style) {
  svg += "<line x1=\"" + number(x1) + "\" y1=\"" + number(y1) + "\" x2=\"" + number(x2) +
         "\" y2=\"" + number(y2) + "\" " + style + "/>\n";
}

void append_text(std::string& svg, double x, double y, const std::string& text,
                 const std::string& attributes) {
  svg += "<text x=\"" + number(x) + "\" y=\"" + number(y) + "\" " + attributes + ">";
  append_escaped(svg, text);
  svg += "</text>\n";
}

std::string open_svg(const Frame& frame, const std::string& css_class, const std::string& title) {
  std::string svg = "<svg class=\"chart " + css_class +
                    "\" xmlns=\"http://www.w3.org/2000/svg\" role=\"img\" viewBox=\"0 0 " +
                    number(frame.width) + " " + number(frame.height) + "\" width=\"" +
                    number(frame.width) + "\" height=\"" + number(frame.height) +
                    "\" font-size=\"13\">\n<title>";
  append_escaped(svg, title);
  return svg + "</title>\n";
}

// Horizontal grid lines with the y ticks, the x ticks, both axes and their labels.
void append_axes(std::string& svg, const Frame& frame, const std::vector<double>& x_ticks,
                 const std::vector<double>& y_ticks, const std::string& x_label,
                 const std::string& y_label) {
  const double bottom = frame.top + frame.plot_height();
  for (const double tick : y_ticks) {
    append_line(svg, frame.left, frame.y(tick), frame.left + frame.plot_width(), frame.y(tick),
                std::string("stroke=\"") + kGridColour + "\"");
    append_text(svg, frame.left - 8, frame.y(tick) + 4, tick_text(tick),
                "text-anchor=\"end\" fill=\"#37474f\"");
  }
  for (const double tick : x_ticks) {
    append_line(svg, frame.x(tick), bottom, frame.x(tick), bottom + 5,
                std::string("stroke=\"") + kAxisColour + "\"");
    append_text(svg, frame.x(tick), bottom + 19, tick_text(tick),
                "text-anchor=\"middle\" fill=\"#37474f\"");
  }
  const std::string axis = std::string("stroke=\"") + kAxisColour + "\" stroke-width=\"1.2\"";
  append_line(svg, frame.left, frame.top, frame.left, bottom, axis);
  append_line(svg, frame.left, bottom, frame.left + frame.plot_width(), bottom, axis);
  append_text(svg, frame.left + frame.plot_width() / 2, frame.height - 8, x_label,
              "text-anchor=\"middle\" fill=\"#263238\"");
  const double middle = frame.top + frame.plot_height() / 2;
  append_text(svg, 16, middle, y_label,
              "text-anchor=\"middle\" fill=\"#263238\" transform=\"rotate(-90 16 " +
                  number(middle) + ")\"");
}

// The y range of the best-so-far values, zero always included, a little room above and below.
void fit_robustness(Frame& frame, const std::vector<BestSoFar>& best) {
  double low = 0, high = 0;
  for (const BestSoFar& point : best) {
    if (!std::isfinite(point.best)) continue;
    low = std::min(low, point.best);
    high = std::max(high, point.best);
  }
  if (high - low < 1e-9) high = low + 1;
  const double margin = (high - low) * 0.08;
  frame.y_low = low < 0 ? low - margin : low;
  frame.y_high = high + margin;
}

// The step line: each best holds until the next one; the last holds to the seed's last
// simulation.
std::string step_path(const Frame& frame, const std::vector<BestSoFar>& best,
                      std::size_t simulations) {
  std::string d;
  for (std::size_t i = 0; i < best.size(); ++i) {
    const double x = frame.x(static_cast<double>(best[i].simulations));
    const double y = frame.y(best[i].best);
    d += i == 0 ? "M" + number(x) + " " + number(y) : " H" + number(x) + " V" + number(y);
  }
  return d + " H" + number(frame.x(static_cast<double>(simulations)));
}

void append_zero_line(std::string& svg, const Frame& frame) {
  const double zero = frame.y(0);
  const double bottom = frame.top + frame.plot_height();
  if (bottom - zero > 0.5)  // the violating side, tinted
    svg += "<rect class=\"violated-region\" x=\"" + number(frame.left) + "\" y=\"" + number(zero) +
           "\" width=\"" + number(frame.plot_width()) + "\" height=\"" + number(bottom - zero) +
           "\" fill=\"#fdecea\"/>\n";
  append_line(svg, frame.left, zero, frame.left + frame.plot_width(), zero,
              std::string("class=\"zero-line\" stroke=\"") + kNewColour +
                  "\" stroke-dasharray=\"6 4\" stroke-width=\"1.2\"");
  append_text(svg, frame.left + frame.plot_width() - 4, zero - 6, "0: violated below",
              std::string("text-anchor=\"end\" font-size=\"12\" fill=\"") + kNewColour + "\"");
}

void append_run_starts(std::string& svg, const Frame& frame, const std::vector<RunStart>& starts) {
  // A label needs about 44 pixels; with many nightly runs only some are labelled.
  double labelled_until = -1e9;
  for (const RunStart& start : starts) {
    const double x = frame.x(static_cast<double>(start.simulations));
    append_line(svg, x, frame.top, x, frame.top + frame.plot_height(),
                "class=\"run-start\" stroke=\"#90a4ae\" stroke-dasharray=\"2 3\"");
    if (x < labelled_until) continue;
    append_text(svg, x + 3, frame.top - 8, "run " + std::to_string(start.run_id),
                "font-size=\"11\" fill=\"#546e7a\"");
    labelled_until = x + 44;
  }
}

std::string no_data_svg(const Frame& frame, const std::string& css_class, const std::string& title,
                        const std::string& message) {
  std::string svg = open_svg(frame, css_class, title);
  append_text(svg, frame.width / 2, frame.height / 2, message,
              "text-anchor=\"middle\" fill=\"#607d8b\"");
  return svg + "</svg>\n";
}

}  // namespace

std::vector<double> axis_ticks(double low, double high, int wanted) {
  const double raw = (high - low) / std::max(wanted, 1);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;
  for (const double factor : {1.0, 2.0, 5.0, 10.0})
    if (power * factor >= raw) {
      step = power * factor;
      break;
    }
  std::vector<double> ticks;
  for (double tick = std::ceil(low / step - 1e-9) * step; tick <= high + step * 1e-9; tick += step)
    ticks.push_back(std::fabs(tick) < step * 1e-9 ? 0.0 : tick);
  return ticks;
}

std::string robustness_chart_svg(const ReportSeed& seed, const std::string& title) {
  Frame frame;
  if (seed.best.empty())
    return no_data_svg(frame, "robustness-chart", title, "no judged simulation yet");
  frame.x_high = static_cast<double>(std::max<std::size_t>(seed.simulations, 1));
  fit_robustness(frame, seed.best);
  std::string svg = open_svg(frame, "robustness-chart", title);
  append_zero_line(svg, frame);
  append_axes(svg, frame, axis_ticks(frame.x_low, frame.x_high, 6),
              axis_ticks(frame.y_low, frame.y_high, 5), "simulations of this seed",
              "best robustness");
  append_run_starts(svg, frame, seed.run_starts);
  svg += "<path class=\"best-so-far\" d=\"" + step_path(frame, seed.best, seed.simulations) +
         "\" fill=\"none\" stroke=\"#1565c0\" stroke-width=\"2.2\"/>\n";
  const BestSoFar& last = seed.best.back();
  append_text(svg, frame.x(static_cast<double>(last.simulations)) + 4,
              frame.y(last.best) + (last.best < 0 ? -6 : 14),
              "best " + (std::isfinite(last.best) ? number_text(last.best, 3)
                                                  : std::string(last.best < 0 ? "-inf" : "inf")),
              "font-size=\"12\" fill=\"#0d47a1\"");
  return svg + "</svg>\n";
}

namespace {

// The bars of one run: seen (stacked: new, regressed, still failing) and fixed beside them.
void append_run_bars(std::string& svg, const Frame& frame, const ReportRun& run, double centre,
                     double bar) {
  const std::size_t still =
      run.modes_seen - std::min(run.modes_seen, run.modes_first_seen + run.regressed);
  double base = 0;
  const auto segment = [&](std::size_t count, const char* colour, const char* css_class, double x) {
    if (count == 0) return;
    std::string label = css_class;  // "still-failing": "still failing"
    std::replace(label.begin(), label.end(), '-', ' ');
    const double top = base + static_cast<double>(count);
    svg += "<rect class=\"bar " + std::string(css_class) + "\" x=\"" + number(x) + "\" y=\"" +
           number(frame.y(top)) + "\" width=\"" + number(bar) + "\" height=\"" +
           number(frame.y(base) - frame.y(top)) + "\" fill=\"" + colour + "\"><title>run " +
           std::to_string(run.run.id) + ": " + std::to_string(count) + " " + label +
           "</title></rect>\n";
    base = top;
  };
  segment(run.modes_first_seen, kNewColour, "new", centre - bar);
  segment(run.regressed, kRegressedColour, "regressed", centre - bar);
  segment(still, kStillFailingColour, "still-failing", centre - bar);
  base = 0;
  segment(run.fixed, kFixedColour, "fixed", centre + 1);
}

// A long version (a full git hash) cut to fit under its bar, never inside a UTF-8 character.
std::string short_version(const std::string& version) {
  if (version.size() <= 12) return version;
  std::size_t end = 11;
  while (end > 0 && (static_cast<unsigned char>(version[end]) & 0xC0) == 0x80) --end;
  return version.substr(0, end) + "…";
}

void append_legend(std::string& svg, const Frame& frame) {
  double x = frame.left;
  for (const auto& [colour, label] :
       {std::pair{kNewColour, "new"}, std::pair{kRegressedColour, "regressed"},
        std::pair{kStillFailingColour, "still failing"}, std::pair{kFixedColour, "fixed"}}) {
    svg += "<rect x=\"" + number(x) + "\" y=\"8\" width=\"12\" height=\"12\" fill=\"" + colour +
           "\"/>\n";
    append_text(svg, x + 17, 19, label, "fill=\"#263238\"");
    x += 30 + 7.0 * static_cast<double>(std::char_traits<char>::length(label));
  }
}

}  // namespace

std::string trend_chart_svg(const std::vector<ReportRun>& runs) {
  Frame frame;
  frame.width = 960;
  frame.height = 320;
  frame.bottom = 64;
  const std::string title = "Failure modes per run";
  if (runs.empty()) return no_data_svg(frame, "trend-chart", title, "no runs yet");
  std::size_t highest = 1;
  for (const ReportRun& run : runs) highest = std::max({highest, run.modes_seen, run.fixed});
  frame.x_high = static_cast<double>(runs.size());
  frame.y_high = static_cast<double>(highest) * 1.1;
  std::vector<double> y_ticks;
  for (const double tick : axis_ticks(0, frame.y_high, 5))
    if (tick == std::floor(tick)) y_ticks.push_back(tick);  // counts: whole numbers only
  std::string svg = open_svg(frame, "trend-chart", title);
  append_axes(svg, frame, {}, y_ticks, "run (start date, ego version)", "failure modes");
  append_legend(svg, frame);
  const double slot = frame.plot_width() / static_cast<double>(runs.size());
  const double bar = std::min(28.0, slot * 0.4);
  // Labels on at most about 12 runs, so they never overlap.
  const std::size_t label_every = (runs.size() + 11) / 12;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const double centre = frame.x(static_cast<double>(i) + 0.5);
    append_run_bars(svg, frame, runs[i], centre, bar);
    if (i % label_every != 0) continue;
    const double bottom = frame.top + frame.plot_height();
    append_text(svg, centre, bottom + 17, "run " + std::to_string(runs[i].run.id),
                "text-anchor=\"middle\" fill=\"#37474f\"");
    append_text(svg, centre, bottom + 31,
                runs[i].run.started.substr(0, 10) + " · " + short_version(runs[i].run.ego_version),
                "text-anchor=\"middle\" font-size=\"11\" fill=\"#607d8b\"");
  }
  return svg + "</svg>\n";
}

}  // namespace scenfuzz
