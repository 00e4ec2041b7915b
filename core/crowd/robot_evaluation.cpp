#include "core/crowd/robot_evaluation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <optional>
#include <sstream>

#include "core/crowd/robot_planners.hpp"

namespace socsim::crowd {
namespace {

// The figures the table summarises, in its column order. Outcome rates are 0/1 per episode;
// time_to_reach_goal counts successful episodes only.
constexpr std::array<const char*, 28> kEvaluationMetrics = {
    "success",
    "collision",
    "collision_person",
    "collision_wall",
    "timeout",
    "stuck",
    "time_to_reach_goal",
    "path_length",
    "path_efficiency",
    "cumulative_heading_changes",
    "avg_distance_to_closest_person",
    "minimum_distance_to_people",
    "intimate_space_intrusions",
    "personal_space_intrusions",
    "social_space_intrusions",
    "group_intimate_space_intrusions",
    "group_personal_space_intrusions",
    "group_social_space_intrusions",
    "collisions",
    "robot_on_person_collision",
    "person_on_robot_collision",
    "time_not_moving",
    "social_force_on_agent",
    "social_force_on_people",
    "social_work",
    "avg_speed",
    "avg_acceleration",
    "avg_jerk",
};

using MetricRow = std::array<std::optional<double>, kEvaluationMetrics.size()>;

MetricRow evaluation_row(const RobotEpisodeMetrics& m) {
  const auto is = [&m](Outcome o) { return m.outcome == o ? 1.0 : 0.0; };
  const bool collided = m.outcome == Outcome::kCollisionPerson || m.outcome == Outcome::kCollisionWall;
  return {is(Outcome::kSuccess),
          collided ? 1.0 : 0.0,
          is(Outcome::kCollisionPerson),
          is(Outcome::kCollisionWall),
          is(Outcome::kTimeout),
          is(Outcome::kStuck),
          m.time_to_reach_goal,
          m.path_length,
          m.path_efficiency,
          m.cumulative_heading_changes,
          m.avg_distance_to_closest_person,
          m.minimum_distance_to_people,
          m.intimate_space_intrusions,
          m.personal_space_intrusions,
          m.social_space_intrusions,
          m.group_intimate_space_intrusions,
          m.group_personal_space_intrusions,
          m.group_social_space_intrusions,
          static_cast<double>(m.collisions),
          static_cast<double>(m.robot_on_person_collision),
          static_cast<double>(m.person_on_robot_collision),
          m.time_not_moving,
          m.social_force_on_agent,
          m.social_force_on_people,
          m.social_work,
          m.avg_speed,
          m.avg_acceleration,
          m.avg_jerk};
}

// Mean of the values present (finite), with their count.
std::pair<std::optional<double>, std::size_t> evaluation_mean(std::span<const std::optional<double>> xs) {
  double sum = 0.0;
  std::size_t n = 0;
  for (const auto& x : xs)
    if (x && std::isfinite(*x)) {
      sum += *x;
      ++n;
    }
  if (n == 0) return {std::nullopt, 0};
  return {sum / static_cast<double>(n), n};
}

Json evaluation_number(const std::optional<double>& x) {
  return x ? Json(*x) : Json(nullptr);
}

// {mean, ci95: [lo, hi] or null for fewer than two values, n}.
Json evaluation_interval(std::span<const std::optional<double>> xs) {
  const auto [mean, n] = evaluation_mean(xs);
  Json j{{"mean", evaluation_number(mean)}, {"ci95", nullptr}, {"n", n}};
  if (n >= 2) {
    double ss = 0.0;
    for (const auto& x : xs)
      if (x && std::isfinite(*x)) ss += (*x - *mean) * (*x - *mean);
    const double sd = std::sqrt(ss / static_cast<double>(n - 1));
    const double half = student_t_975(n - 1) * sd / std::sqrt(static_cast<double>(n));
    j["ci95"] = {*mean - half, *mean + half};
  }
  return j;
}

std::string evaluation_fixed(double x, int digits) {
  std::ostringstream s;
  s.imbue(std::locale::classic());
  s.setf(std::ios::fixed);
  s.precision(digits);
  s << x;
  return s.str();
}

}  // namespace

double student_t_975(std::size_t df) {
  static constexpr std::array<double, 31> kTable = {0.0,   12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365,
                                                    2.306, 2.262,  2.228, 2.201, 2.179, 2.160, 2.145, 2.131,
                                                    2.120, 2.110,  2.101, 2.093, 2.086, 2.080, 2.074, 2.069,
                                                    2.064, 2.060,  2.056, 2.052, 2.048, 2.045, 2.042};
  if (df == 0) return std::nan("");
  if (df < kTable.size()) return kTable[df];
  // Cornish-Fisher expansion about z = 1.959964; within 1e-4 of the quantile beyond 30.
  const double z = 1.959964, v = static_cast<double>(df);
  return z + (z * z * z + z) / (4 * v) + (5 * std::pow(z, 5) + 16 * z * z * z + 3 * z) / (96 * v * v);
}

Result<EvaluationEpisode> run_planner_episode(const EvaluationPlan& plan, std::size_t scenario,
                                              std::size_t planner, std::size_t seed) {
  const EvaluationScenario& s = plan.scenarios.at(scenario);
  RunnerOptions options;
  options.seed = plan.seeds.at(seed);
  options.record_metrics = false;
  options.robots = plan.robots;
  auto episode = Episode::create(s.world.get(), *s.program, options, plan.episode);
  if (!episode)
    return tl::unexpected(Error(episode.error().code, "card '" + s.id + "': " + episode.error().detail,
                                episode.error().errors));
  const auto p = make_planner(plan.planner_names.at(planner));
  if (!p) return fail(ErrorCode::kValidation, "unknown planner '" + plan.planner_names[planner] + "'");
  Episode& e = **episode;
  std::vector<RobotInput> inputs(e.robots().size());
  while (!e.ended()) {
    for (std::size_t k = 0; k < inputs.size(); ++k)
      inputs[k] = RobotInput{RobotInput::Kind::kCommand, p->plan(planner_input(e, k)), {}, {}};
    if (auto ok = e.step(inputs); !ok) return tl::unexpected(ok.error());
  }
  EvaluationEpisode out;
  out.scenario = scenario;
  out.planner = planner;
  out.seed = seed;
  out.steps = e.steps();
  out.metrics = evaluate_episode(e.log()).robots.at(0);
  return out;
}

Result<std::vector<EvaluationEpisode>> run_evaluation(const EvaluationPlan& plan,
                                                      const EvaluationHooks& hooks) {
  const std::size_t total = plan.scenarios.size() * plan.planners.size() * plan.seeds.size();
  std::vector<EvaluationEpisode> out;
  out.reserve(total);
  for (std::size_t s = 0; s < plan.scenarios.size(); ++s)
    for (std::size_t p = 0; p < plan.planners.size(); ++p)
      for (std::size_t k = 0; k < plan.seeds.size(); ++k) {
        if (hooks.cancelled && hooks.cancelled())
          return fail(ErrorCode::kCancelled, "the evaluation was cancelled");
        auto e = run_planner_episode(plan, s, p, k);
        if (!e) return tl::unexpected(e.error());
        out.push_back(std::move(*e));
        if (hooks.progress) hooks.progress(out.size(), total);
      }
  return out;
}

Json evaluation_table(const EvaluationPlan& plan, std::span<const EvaluationEpisode> episodes) {
  const std::size_t S = plan.scenarios.size(), P = plan.planners.size();
  // cell_rows[s][p]: the episodes' rows; cell_means[p][m][s]: the cell's mean of metric m.
  std::vector<std::vector<std::vector<MetricRow>>> cell_rows(S, std::vector<std::vector<MetricRow>>(P));
  std::vector<std::vector<std::vector<Outcome>>> cell_outcomes(S, std::vector<std::vector<Outcome>>(P));
  for (const EvaluationEpisode& e : episodes) {
    cell_rows.at(e.scenario).at(e.planner).push_back(evaluation_row(e.metrics));
    cell_outcomes[e.scenario][e.planner].push_back(e.metrics.outcome);
  }
  std::vector<std::vector<std::vector<std::optional<double>>>> cell_means(
      P, std::vector<std::vector<std::optional<double>>>(kEvaluationMetrics.size()));

  Json cells = Json::array();
  for (std::size_t s = 0; s < S; ++s)
    for (std::size_t p = 0; p < P; ++p) {
      const auto& rows = cell_rows[s][p];
      Json mean = Json::object();
      for (std::size_t m = 0; m < kEvaluationMetrics.size(); ++m) {
        std::vector<std::optional<double>> xs;
        for (const MetricRow& r : rows) xs.push_back(r[m]);
        const auto avg = evaluation_mean(xs).first;
        mean[kEvaluationMetrics[m]] = evaluation_number(avg);
        cell_means[p][m].push_back(avg);
      }
      Json outcomes = Json::object();
      for (Outcome o : cell_outcomes[s][p]) {
        const std::string name(outcome_name(o));
        outcomes[name] = outcomes.value(name, 0) + 1;
      }
      cells.push_back({{"card", plan.scenarios[s].id},
                       {"planner", plan.planners[p]},
                       {"episodes", rows.size()},
                       {"outcomes", outcomes},
                       {"mean", mean}});
    }

  Json planners = Json::array();
  std::vector<double> collision_rate(P, 0.0);
  for (std::size_t p = 0; p < P; ++p) {
    Json metrics = Json::object();
    for (std::size_t m = 0; m < kEvaluationMetrics.size(); ++m)
      metrics[kEvaluationMetrics[m]] = evaluation_interval(cell_means[p][m]);
    collision_rate[p] =
        metrics["collision"]["mean"].is_number() ? metrics["collision"]["mean"].get<double>() : 0.0;
    std::size_t n = 0;
    for (std::size_t s = 0; s < S; ++s) n += cell_rows[s][p].size();
    planners.push_back({{"planner", plan.planners[p]}, {"episodes", n}, {"cards", S}, {"metrics", metrics}});
  }

  // Planners from fewest collision outcomes to most (ties keep the request's order).
  std::vector<std::size_t> order(P);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&collision_rate](std::size_t a, std::size_t b) {
    return collision_rate[a] < collision_rate[b];
  });
  Json by_collisions = Json::array();
  for (std::size_t p : order) by_collisions.push_back(plan.planners[p]);

  // One line per planner, for logs and the docs.
  std::vector<std::string> summary;
  for (std::size_t p = 0; p < P; ++p) {
    const Json& m = planners[p]["metrics"];
    const auto fig = [&m](const char* name, int digits) {
      const Json& f = m[name];
      if (!f["mean"].is_number()) return std::string("n/a");
      std::string text = evaluation_fixed(f["mean"].get<double>(), digits);
      if (f["ci95"].is_array())
        text += " [" + evaluation_fixed(f["ci95"][0].get<double>(), digits) + ", " +
                evaluation_fixed(f["ci95"][1].get<double>(), digits) + "]";
      return text;
    };
    summary.push_back(plan.planners[p] + ": success " + fig("success", 2) + ", collision " +
                      fig("collision", 2) + ", time to goal " + fig("time_to_reach_goal", 1) + " s, path " +
                      fig("path_length", 1) + " m, min distance " + fig("minimum_distance_to_people", 2) +
                      " m, intimate " + fig("intimate_space_intrusions", 1) + " %");
  }

  Json metric_names = Json::array();
  for (const char* m : kEvaluationMetrics) metric_names.push_back(m);
  return {{"interval",
           "95 % Student-t interval over the cards' means (n = cards; each card's mean is over its seeds)"},
          {"cards", S},
          {"seeds", plan.seeds},
          {"metrics", metric_names},
          {"cells", cells},
          {"planners", planners},
          {"ranking", {{"collision", by_collisions}}},
          {"summary", summary}};
}

}  // namespace socsim::crowd
