#include "sweep/sweep_report.hpp"

#include "io/json_text.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace fr {
namespace {

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string label(const SweepRow& r) {
  return r.knob == "default" ? "default" : r.knob + "=" + r.value;
}

// The error axis of the plot and the front: mean absolute error, floored so that a perfect
// configuration still has a place on a log scale.
double plotted_error(const SweepRow& r) {
  return std::max(r.error.mean_abs_error, 1e-3);
}

}  // namespace

void analyse_sweep(SweepResult& result, double lanes_pixel_difference) {
  std::vector<double> time, error;
  for (const auto& r : result.rows) {
    time.push_back(r.frame_ms);
    error.push_back(r.error.mean_abs_error);
  }
  for (size_t i : pareto_front(time, error)) result.rows[i].on_front = true;
  for (const auto& d : result.rows) {
    if (d.knob != "default") continue;
    if (d.on_front) {
      result.notes.push_back("the default settings are on the Pareto front");
      break;
    }
    // The best error any front point reaches in no more time than the default (+10%).
    double best = INFINITY;
    for (const auto& r : result.rows)
      if (r.on_front && r.frame_ms <= 1.1 * d.frame_ms)
        best = std::min(best, r.error.mean_abs_error);
    if (d.error.mean_abs_error <= 1.1 * best + 0.05)
      result.notes.push_back("the default settings are next to the Pareto front (error " +
                             fmt("%.3f", d.error.mean_abs_error) + " vs " + fmt("%.3f", best) +
                             " on the front at its time)");
    else
      result.notes.push_back("the default settings are OFF the Pareto front: error " +
                             fmt("%.3f", d.error.mean_abs_error) + " where the front reaches " +
                             fmt("%.3f", best) + " in the same time");
  }
  if (lanes_pixel_difference >= 0)
    result.notes.push_back(
        lanes_pixel_difference <= 0.005
            ? "lane widths 1 and 16 are error-neutral (" +
                  fmt("%.2f", 100 * lanes_pixel_difference) + "% of pixels differ by > 2/255)"
            : "lane widths are NOT error-neutral: " + fmt("%.2f", 100 * lanes_pixel_difference) +
                  "% of pixels differ by > 2/255 between widths 1 and 16");
}

std::string format_sweep_table(const SweepResult& s) {
  std::ostringstream out;
  char line[320];
  std::snprintf(line, sizeof line, "%-26s %9s %8s %7s %7s %8s %8s %7s %8s %7s %7s %5s\n",
                "configuration", "frame ms", "MAE", "PSNR", ">8/255", "depth50", "depth95", "silh.",
                "normal95", "overst.", "no-conv", "NaN");
  out << line;
  for (const auto& r : s.rows) {
    std::snprintf(line, sizeof line,
                  "%-26s %9.2f %8.3f %7.2f %6.2f%% %8.3f %8.3f %6.2f%% %7.2fd %6.2f%% %6.2f%% "
                  "%5zu%s\n",
                  label(r).c_str(), r.frame_ms, r.error.mean_abs_error,
                  std::isfinite(r.error.psnr_db) ? r.error.psnr_db : 99.99,
                  100 * r.error.fraction_over_8, r.error.depth_median_px, r.error.depth_p95_px,
                  100 * r.error.silhouette_mismatch, r.error.normal_p95_deg,
                  100 * r.error.overstep_rate, 100 * r.error.out_of_steps_fraction,
                  r.error.non_finite, r.on_front ? "  *front" : "");
    out << line;
  }
  out << "(MAE and >8/255 against the reference picture, 8-bit units; depth in pixel footprints; "
         "no-conv: rays out of steps)\n";
  return out.str();
}

std::string format_sweep_csv(const SweepResult& s) {
  std::ostringstream out;
  out << "knob,value,frame_ms,mean_abs_error,psnr_db,fraction_over_8,depth_median_px,"
         "depth_p95_px,silhouette_mismatch,normal_p95_deg,overstep_rate,out_of_steps_fraction,"
         "non_finite,on_pareto_front\n";
  for (const auto& r : s.rows) {
    const ErrorMetrics& e = r.error;
    out << r.knob << ',' << r.value << ',' << fmt("%.4f", r.frame_ms) << ','
        << fmt("%.6g", e.mean_abs_error) << ','
        << (std::isfinite(e.psnr_db) ? fmt("%.4f", e.psnr_db) : "inf") << ','
        << fmt("%.6g", e.fraction_over_8) << ',' << fmt("%.6g", e.depth_median_px) << ','
        << fmt("%.6g", e.depth_p95_px) << ',' << fmt("%.6g", e.silhouette_mismatch) << ','
        << fmt("%.6g", e.normal_p95_deg) << ',' << fmt("%.6g", e.overstep_rate) << ','
        << fmt("%.6g", e.out_of_steps_fraction) << ',' << e.non_finite << ','
        << (r.on_front ? 1 : 0) << '\n';
  }
  return out.str();
}

std::string format_sweep_json(const SweepResult& s) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const SweepRow& r : s.rows) {
    const ErrorMetrics& e = r.error;
    rows.push_back({{"knob", r.knob},
                    {"value", r.value},
                    {"frame_ms", r.frame_ms},
                    {"mean_abs_error", e.mean_abs_error},
                    {"psnr_db", e.psnr_db},  // an identical image's infinity is written as null
                    {"fraction_over_8", e.fraction_over_8},
                    {"depth_median_px", e.depth_median_px},
                    {"depth_p95_px", e.depth_p95_px},
                    {"silhouette_mismatch", e.silhouette_mismatch},
                    {"normal_p95_deg", e.normal_p95_deg},
                    {"overstep_rate", e.overstep_rate},
                    {"out_of_steps_fraction", e.out_of_steps_fraction},
                    {"non_finite", e.non_finite},
                    {"on_pareto_front", r.on_front}});
  }
  const nlohmann::ordered_json j = {
      {"scene", s.scene_id},
      {"device", s.device},
      {"resolution", {{"width", s.width_px}, {"height", s.height_px}}},
      {"timed_frames", s.timed_frames},
      {"reference",
       {{"hit_threshold_k", s.reference.hit_threshold_k},
        {"refinements", s.reference.refinements},
        {"samples", s.reference.samples},
        {"convergence_mean_abs_error", s.reference.convergence_mae},
        {"convergence_depth_px", s.reference.convergence_depth_px}}},
      {"notes", s.notes},
      {"configurations", rows},
  };
  return json_text(j);
}

std::string format_sweep_svg(const SweepResult& s) {
  const double W = 760, H = 460, left = 70, right = 110, top = 40, bottom = 50;
  double t_lo = INFINITY, t_hi = 0, e_lo = INFINITY, e_hi = 0;
  for (const auto& r : s.rows) {
    t_lo = std::min(t_lo, r.frame_ms);
    t_hi = std::max(t_hi, r.frame_ms);
    e_lo = std::min(e_lo, plotted_error(r));
    e_hi = std::max(e_hi, plotted_error(r));
  }
  // Log axes, padded to whole powers of ten around the data.
  const double lt0 = std::floor(std::log10(std::max(t_lo, 1e-3))),
               lt1 = std::ceil(std::log10(std::max(t_hi, 1e-3)) + 1e-9);
  const double le0 = std::floor(std::log10(e_lo)), le1 = std::ceil(std::log10(e_hi) + 1e-9);
  auto x = [&](double t) {
    return left +
           (std::log10(std::max(t, 1e-3)) - lt0) / std::max(lt1 - lt0, 1.0) * (W - left - right);
  };
  auto y = [&](double e) {
    return H - bottom - (std::log10(e) - le0) / std::max(le1 - le0, 1.0) * (H - top - bottom);
  };
  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << W / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"14\">"
      << s.scene_id << " " << s.width_px << "x" << s.height_px
      << ": image error against frame time</text>\n";
  for (double p = lt0; p <= lt1 + 1e-9; ++p)
    out << "<line x1=\"" << x(std::pow(10, p)) << "\" y1=\"" << top << "\" x2=\""
        << x(std::pow(10, p)) << "\" y2=\"" << H - bottom << "\" stroke=\"#ddd\"/><text x=\""
        << x(std::pow(10, p)) << "\" y=\"" << H - bottom + 16 << "\" text-anchor=\"middle\">"
        << fmt("%g", std::pow(10, p)) << "</text>\n";
  for (double p = le0; p <= le1 + 1e-9; ++p)
    out << "<line x1=\"" << left << "\" y1=\"" << y(std::pow(10, p)) << "\" x2=\"" << W - right
        << "\" y2=\"" << y(std::pow(10, p)) << "\" stroke=\"#ddd\"/><text x=\"" << left - 6
        << "\" y=\"" << y(std::pow(10, p)) + 4 << "\" text-anchor=\"end\">"
        << fmt("%g", std::pow(10, p)) << "</text>\n";
  out << "<text x=\"" << (left + W - right) / 2 << "\" y=\"" << H - 12
      << "\" text-anchor=\"middle\">frame time, ms (median, log scale)</text>\n"
      << "<text transform=\"translate(16," << (top + H - bottom) / 2
      << ") rotate(-90)\" text-anchor=\"middle\">mean absolute error vs reference, 8-bit "
         "(log)</text>\n";
  // The front as a line, then every configuration, the default in red.
  std::vector<const SweepRow*> front;
  for (const auto& r : s.rows)
    if (r.on_front) front.push_back(&r);
  std::sort(front.begin(), front.end(),
            [](const SweepRow* a, const SweepRow* b) { return a->frame_ms < b->frame_ms; });
  out << "<polyline fill=\"none\" stroke=\"#2a7\" stroke-width=\"2\" points=\"";
  for (const SweepRow* r : front) out << x(r->frame_ms) << "," << y(plotted_error(*r)) << " ";
  out << "\"/>\n";
  // Every configuration as a dot; only the front and the defaults are labelled (the CSV names
  // the rest), and the defaults are drawn last, on top.
  std::vector<const SweepRow*> order;
  for (const auto& r : s.rows) order.push_back(&r);
  std::stable_partition(order.begin(), order.end(),
                        [](const SweepRow* r) { return r->knob != "default"; });
  for (const SweepRow* r : order) {
    const bool is_default = r->knob == "default";
    out << "<circle cx=\"" << x(r->frame_ms) << "\" cy=\"" << y(plotted_error(*r)) << "\" r=\""
        << (is_default ? 6 : 4) << "\" fill=\""
        << (is_default    ? "#d22"
            : r->on_front ? "#2a7"
                          : "#9ab")
        << "\"/>\n";
    if (is_default || r->on_front)
      out << "<text x=\"" << x(r->frame_ms) + 7 << "\" y=\"" << y(plotted_error(*r)) - 6
          << "\" fill=\"" << (is_default ? "#d22" : "#333") << "\""
          << (is_default ? " font-weight=\"bold\"" : "") << ">" << label(*r) << "</text>\n";
  }
  out << "<text x=\"" << W - right << "\" y=\"" << top - 4
      << "\" text-anchor=\"end\" fill=\"#2a7\">green: the Pareto front; red: the defaults; grey: "
         "the rest</text>\n"
      << "</svg>\n";
  return out.str();
}

}  // namespace fr
