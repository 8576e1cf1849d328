// hwinterp plan: fewest straight segments for a cam pitch curve within +-E
// (optimal linear interpolation, models/optimal_linear.h), or Nishioka's
// chords for comparison, each checked by the independent polyline verifier.
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "models/cam_profile.h"
#include "models/common.h"
#include "models/nishioka.h"
#include "models/optimal_linear.h"
#include "models/polyline_verifier.h"
#include "tb/base/text_table.h"
#include "tb/cli/subcommand.h"

namespace hwinterp::cli {
namespace {
using models::kPi;

using models::Vec2;

// The verifier's own rounding: it finds feet of normals to ~1e-13 mm, and
// the paper's first stopping rule may leave the last segment ~1e-10 mm over.
constexpr double kVerifySlack = 1e-9;
// Below this the 1e-8 mm convergence limit is no longer small against E.
constexpr double kMinTolerance = 1e-7;
constexpr double kMaxLength = 1e6;  // mm: a cam larger than a kilometre is a typo

// A value that must be positive (and sane); names the option on failure.
double positive(const Args& args, const std::string& name, double hi = kMaxLength) {
  const double v = args.real(name);
  if (!(v > 0)) throw UsageError("--" + name + ": " + args.str(name) + " must be positive");
  if (v > hi) {
    std::ostringstream os;
    os << "--" << name << ": " << args.str(name) << " exceeds " << hi;
    throw UsageError(os.str());
  }
  return v;
}

struct Cam {
  std::unique_ptr<models::PlanarCurve> curve;
  double outward_sign = 1;
  bool rotating = false;
  std::string options;  // the options that shape the curve, as given ("--r0 40 --lift 30 ...")
  Json json = Json::object();
};

Cam make_cam(const Args& args, models::CamLaw law) {
  Cam cam;
  cam.rotating = args.given("rotating");
  const auto forbid = [&](const char* name, const char* kind) {
    if (args.given(name))
      throw UsageError(std::string("--") + name + " " + args.str(name) + " does not apply to a " +
                       kind + " cam (" +
                       (cam.rotating ? "--rotating takes --r0, --lift, --theta-d"
                                     : "a translating cam takes --stroke, --lift; add --rotating "
                                       "for --r0, --theta-d") +
                       ")");
  };
  const auto require = [&](const char* name) {
    if (!args.given(name))
      throw UsageError(std::string("--") + name + " is required for a " +
                       (cam.rotating ? "rotating" : "translating") + " cam");
  };
  cam.json["law"] = models::cam_law_name(law);
  if (cam.rotating) {
    forbid("stroke", "rotating");
    for (const char* n : {"r0", "lift", "theta-d"}) require(n);
    const double r0 = positive(args, "r0"), lift = positive(args, "lift");
    const double theta_d = positive(args, "theta-d", 360);
    cam.curve = std::make_unique<models::RotatingCam>(law, r0, lift, theta_d * kPi / 180);
    cam.outward_sign = static_cast<const models::RotatingCam&>(*cam.curve).outward_sign();
    cam.json["type"] = "rotating";
    cam.json["r0"] = r0;
    cam.json["lift"] = lift;
    cam.json["theta_d_deg"] = theta_d;
    cam.options = "--r0 " + args.str("r0") + " --lift " + args.str("lift") + " --theta-d " +
                  args.str("theta-d");
  } else {
    forbid("r0", "translating");
    forbid("theta-d", "translating");
    for (const char* n : {"stroke", "lift"}) require(n);
    const double stroke = positive(args, "stroke"), lift = positive(args, "lift");
    cam.curve = std::make_unique<models::TranslatingCam>(law, stroke, lift);
    cam.outward_sign = static_cast<const models::TranslatingCam&>(*cam.curve).outward_sign();
    cam.json["type"] = "translating";
    cam.json["stroke"] = stroke;
    cam.json["lift"] = lift;
    cam.options = "--stroke " + args.str("stroke") + " --lift " + args.str("lift");
  }
  return cam;
}

// What the planners hand over: the polyline and its intervals.
struct Interval {
  double t_begin = 0, t_end = 0;
  int sign = 0;
  int segments = 0;
  double error = 0;  // OLI: the achieved e; Nishioka: its nominal error
};

struct Polyline {
  std::vector<Vec2> vertices;
  std::vector<Interval> intervals;
  int segments = 0;
  double error = 0;
};

Polyline run_optimal(const models::PlanarCurve& curve, double tol) {
  const models::OliPlan plan = models::plan_optimal_linear(curve, tol);
  Polyline out;
  out.vertices = plan.vertices;
  out.segments = plan.segments;
  out.error = plan.error;
  for (const auto& iv : plan.intervals)
    out.intervals.push_back({iv.t_begin, iv.t_end, iv.sign, iv.segments, iv.error});
  return out;
}

Polyline run_nishioka(const models::PlanarCurve& curve, double tol) {
  // Interval by interval, as the paper's comparison splits Cam 1 at its
  // inflection.
  std::vector<double> cuts{curve.t_begin()};
  for (double t : models::find_inflections(curve)) cuts.push_back(t);
  cuts.push_back(curve.t_end());
  Polyline out;
  for (size_t j = 0; j + 1 < cuts.size(); ++j) {
    const models::NishiokaPlan part = models::plan_nishioka(curve, cuts[j], cuts[j + 1], tol);
    out.vertices.insert(out.vertices.end(), part.vertices.begin() + (j == 0 ? 0 : 1),
                        part.vertices.end());
    out.intervals.push_back({cuts[j], cuts[j + 1],
                             models::curvature_sign(curve, cuts[j], cuts[j + 1]), part.segments,
                             tol});
    out.segments += part.segments;
  }
  out.error = tol;
  return out;
}

std::string segments_csv(const Polyline& p) {
  std::ostringstream os;
  os.precision(17);
  os << "segment,x0,y0,x1,y1,length\n";
  for (size_t i = 0; i + 1 < p.vertices.size(); ++i) {
    const Vec2& a = p.vertices[i];
    const Vec2& b = p.vertices[i + 1];
    os << i << ',' << a.x() << ',' << a.y() << ',' << b.x() << ',' << b.y() << ',' << (b - a).norm()
       << '\n';
  }
  return os.str();
}

std::string error_csv(const models::PlanarCurve& curve, const Polyline& p, double side,
                      bool rotating, double tol) {
  const auto samples = models::sample_polyline_error(curve, p.vertices, 24, side);
  std::ostringstream os;
  os.precision(12);
  // The header names the parameter and carries the tolerance for the plot.
  os << "segment," << (rotating ? "theta_deg" : "x_mm") << ",position_mm,x,y,error_mm,tol_mm\n";
  for (const auto& s : samples) {
    os << s.segment << ',' << (rotating ? s.t_foot * 180 / kPi : s.t_foot) << ',' << s.arc_length
       << ',' << s.point.x() << ',' << s.point.y() << ',' << s.error << ',' << tol << '\n';
  }
  return os.str();
}

int run_plan(int argc, char** argv, int first) {
  Args args("plan",
            "Fewest straight segments for a cam pitch curve within +-TOL mm, the error measured\n"
            "along the curve normal (optimal linear interpolation), or Nishioka's chords for\n"
            "comparison. Every polyline is checked by an independent verifier; exit 1 when its\n"
            "error exceeds TOL (Nishioka's usually does: its nominal error is not the normal\n"
            "error). Translating cam: y = lift S(x / stroke); rotating cam (--rotating): radius\n"
            "r0 + lift S(theta / theta_d). Errors are positive away from the cam body.");
  std::string laws;
  for (const auto& n : models::cam_law_names()) laws += (laws.empty() ? "" : "|") + n;
  args.option("law", "LAW", "cam law: " + laws)
      .option("tol", "MM", "tolerance E: the largest normal error allowed")
      .option("stroke", "MM", "translating cam: stroke (x range)")
      .option("lift", "MM", "follower lift")
      .flag("rotating", "rotating cam with a radial follower")
      .option("r0", "MM", "rotating cam: prime circle radius")
      .option("theta-d", "DEG", "rotating cam: rise angle, in (0, 360]")
      .option("method", "NAME",
              "optimal|nishioka (Nishioka: chords with the Eq. A-4 error = TOL, each "
              "convex/concave interval in its own pass)",
              "optimal")
      .option("csv", "FILE", "write the segments (segment,x0,y0,x1,y1,length)")
      .option("error-csv", "FILE",
              "write the normal error sampled along the contour (for "
              "scripts/plot_contour_error.py)");
  if (parse_or_help(args, argc, argv, first)) return kExitOk;

  stage_outputs(args, {"csv", "error-csv"});
  if (!args.given("law")) throw UsageError("--law is required (" + laws + ")");
  const models::CamLaw law = models::parse_cam_law(args.choice("law", models::cam_law_names()));
  if (!args.given("tol")) throw UsageError("--tol is required");
  const double tol = args.real("tol");
  if (!(tol > 0)) throw UsageError("--tol: " + args.str("tol") + " must be positive");
  if (tol < kMinTolerance) {
    std::ostringstream os;
    os << "--tol: " << args.str("tol") << " is below " << kMinTolerance
       << " mm (the planner converges to 1e-8 mm)";
    throw UsageError(os.str());
  }
  const std::string method = args.choice("method", {"optimal", "nishioka"});
  Cam cam = make_cam(args, law);

  const auto t0 = std::chrono::steady_clock::now();
  Polyline poly;
  try {
    poly = method == "optimal" ? run_optimal(*cam.curve, tol) : run_nishioka(*cam.curve, tol);
  } catch (const std::invalid_argument& e) {
    // The planner's refusals (tolerance too coarse or too fine for this
    // curve, a curve it cannot split) are bad input: the tolerance and the
    // options that shape the curve together.
    throw UsageError("--tol " + args.str("tol") + " with " + cam.options + ": " + e.what());
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  models::PolylineCheckOptions vopt;
  vopt.side_sign = cam.outward_sign;
  const models::PolylineCheck check = models::verify_polyline(*cam.curve, poly.vertices, vopt);
  const bool ok = check.max_abs_error <= tol + kVerifySlack && check.samples_past_ends == 0;

  // Human summary.
  const auto param = [&](double t) { return cam.rotating ? t * 180 / kPi : t; };
  std::cout << "plan: " << method << ", " << models::cam_law_name(law) << " "
            << (cam.rotating ? "rotating" : "translating") << " cam, tolerance +-" << tol
            << " mm\n";
  TextTable table({"interval", cam.rotating ? "theta from (deg)" : "x from (mm)",
                   cam.rotating ? "theta to (deg)" : "x to (mm)", "bend", "segments",
                   method == "optimal" ? "error e (mm)" : "nominal (mm)"});
  for (size_t i = 0; i < poly.intervals.size(); ++i) {
    const Interval& iv = poly.intervals[i];
    // Paper's words: convex when the chord lies on the body side.
    const double body_left = -cam.outward_sign;
    const char* bend = iv.sign == 0 ? "straight" : (iv.sign * body_left > 0 ? "convex" : "concave");
    table.add_row({std::to_string(i + 1), fmt("%.6f", param(iv.t_begin)),
                   fmt("%.6f", param(iv.t_end)), bend, std::to_string(iv.segments),
                   fmt("%.6g", iv.error)});
  }
  table.add_row({"whole", fmt("%.6f", param(cam.curve->t_begin())),
                 fmt("%.6f", param(cam.curve->t_end())), "", std::to_string(poly.segments),
                 fmt("%.6g", poly.error)});
  std::cout << table.render();
  std::cout << "verified: max |error| " << fmt("%.6g", check.max_abs_error) << " mm (+"
            << fmt("%.6g", check.most_positive.error) << " / "
            << fmt("%.6g", check.most_negative.error) << "), worst on segment "
            << check.worst.segment + 1 << " at (" << fmt("%.4f", check.worst.point.x()) << ", "
            << fmt("%.4f", check.worst.point.y()) << ")" << (ok ? "" : "  -> EXCEEDS the tolerance")
            << "\n";
  std::cout << "planned in " << fmt("%.3f", seconds * 1e3) << " ms\n";

  if (args.given("csv")) write_text_file(output_path("csv"), segments_csv(poly), "--csv");
  if (args.given("error-csv"))
    write_text_file(output_path("error-csv"),
                    error_csv(*cam.curve, poly, cam.outward_sign, cam.rotating, tol),
                    "--error-csv");

  Json report = Json::object();
  report["method"] = method;
  report["cam"] = std::move(cam.json);
  report["tolerance"] = tol;
  report["segments"] = poly.segments;
  report["error"] = poly.error;
  report["verified_max_error"] = check.max_abs_error;
  report["verified_max_positive"] = check.most_positive.error;
  report["verified_max_negative"] = check.most_negative.error;
  Json worst = Json::object();
  worst["segment"] = check.worst.segment;
  worst["x"] = check.worst.point.x();
  worst["y"] = check.worst.point.y();
  worst["t_foot"] = check.worst.t_foot;
  report["verified_worst"] = std::move(worst);
  // Interval bounds are curve parameters: x in mm, or theta in radians.
  report["parameter"] = cam.rotating ? "theta_rad" : "x_mm";
  Json intervals = Json::array();
  for (const Interval& iv : poly.intervals) {
    Json j = Json::object();
    j["t_begin"] = iv.t_begin;
    j["t_end"] = iv.t_end;
    j["segments"] = iv.segments;
    j["error"] = iv.error;
    intervals.push_back(std::move(j));
  }
  report["intervals"] = std::move(intervals);
  report["seconds"] = seconds;
  report["ok"] = ok;
  maybe_write_json(args, report);
  return ok ? kExitOk : kExitCheckFailed;
}

}  // namespace

HWINTERP_SUBCOMMAND("plan", "fewest segments for a cam contour within a tolerance (OLI)", 40,
                    run_plan);

}  // namespace hwinterp::cli
