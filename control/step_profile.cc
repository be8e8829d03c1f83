#include "control/step_profile.h"

#include <algorithm>
#include <cmath>

#include "dynamics/kinematics.h"

namespace walkers {

namespace {

constexpr std::array<WalkingState, 3> kWalkingStates = {WalkingState::kDoubleSupport, WalkingState::kLeftSupport,
                                                        WalkingState::kRightSupport};

const char* StopName(int stop) { return kCoordNames[kHipL + stop]; }

}  // namespace

const std::array<std::string, kNumStateComponents>& StateComponentNames() {
  static const std::array<std::string, kNumStateComponents> names = [] {
    std::array<std::string, kNumStateComponents> out;
    for (int i = 0; i < kNumCoords; ++i) {
      out[i] = std::string("q_") + kCoordNames[i];
      out[kNumCoords + i] = std::string("v_") + kCoordNames[i];
    }
    return out;
  }();
  return names;
}

ContactSet ContactSetAt(const Model& model, const State& state, const Welds& welds) {
  ContactSet set;
  Kinematics kin;
  ComputeKinematics(model, state.q, state.v, &kin);
  const ContactReports reports = ReportContacts(model, kin);
  for (int pair = 0; pair < kNumContactPairs; ++pair) {
    // a welded foot's ground contact is not applied (AddContactForces)
    if (!HeldByWeld(ContactPairs()[pair], welds)) set.elements[pair] = reports[pair].elements;
  }
  // a stop pushes past +-limit (JointStopTorque)
  for (int leg = 0; leg < kNumLegs; ++leg) {
    for (int joint = 0; joint < kNumJoints; ++joint) {
      const int i = JointIndex(leg, joint);
      set.stops[leg * kNumJoints + joint] =
          model.options.joint_stops && std::abs(state.q(i)) > model.stops[joint].limit;
    }
  }
  return set;
}

long TickProfile::PairSwitches() const {
  long n = 0;
  for (long s : pair_switches) n += s;
  return n;
}

long TickProfile::StopSwitches() const {
  long n = 0;
  for (long s : stop_switches) n += s;
  return n;
}

StepProfile::StepProfile(const Model& model) : model_(model) {}

void StepProfile::OnTick(double t, const State& state, const WalkingController& controller) {
  if (!has_previous_) {
    previous_ = ContactSetAt(model_, state, controller.inputs().welds);
    has_previous_ = true;
  }
  TickProfile tick;
  tick.t = t;
  tick.state = controller.state();
  ticks_.push_back(tick);
}

void StepProfile::OnStep(const StepInfo& step) {
  if (ticks_.empty()) ticks_.emplace_back();  // a step before any tick: a tick of its own at t = 0
  TickProfile& tick = ticks_.back();
  tick.step_min = tick.steps == 0 ? step.step : std::min(tick.step_min, step.step);
  tick.step_max = tick.steps == 0 ? step.step : std::max(tick.step_max, step.step);
  ++tick.steps;
  tick.step_sum += step.step;
  tick.max_order = std::max(tick.max_order, step.order);
  tick.error_test_failures += step.error_test_failures;
  tick.nonlinear_failures += step.nonlinear_failures;

  // the component with the largest weighted local error (none if all are zero)
  int limiting = 0;
  const double largest = step.weighted_error.maxCoeff(&limiting);
  if (largest > 0.0) ++tick.limiting[limiting];

  // what switched since the previous step
  const ContactSet now = ContactSetAt(model_, *step.state, step.inputs->welds);
  if (has_previous_) {
    for (int pair = 0; pair < kNumContactPairs; ++pair) {
      tick.pair_switches[pair] += (now.elements[pair] > 0) != (previous_.elements[pair] > 0) ? 1 : 0;
      tick.spring_switches += std::abs(now.elements[pair] - previous_.elements[pair]);
    }
    for (int stop = 0; stop < kNumJointStops; ++stop) {
      tick.stop_switches[stop] += now.stops[stop] != previous_.stops[stop] ? 1 : 0;
    }
  }
  previous_ = now;
  has_previous_ = true;
  tick.at_end = now;
}

std::vector<TickProfile> StepProfile::Ticks() const {
  std::vector<TickProfile> out;
  std::copy_if(ticks_.begin(), ticks_.end(), std::back_inserter(out), [](const TickProfile& t) { return t.steps > 0; });
  return out;
}

void StepProfile::WriteCsv(std::ostream& out) const {
  out << "t,state,steps,error_test_failures,nonlinear_failures,step_mean,step_min,step_max,max_order";
  for (const std::string& name : StateComponentNames()) out << ",limit_" << name;
  out << ",pairs_on,springs_on,stops_on,pair_switches,spring_switches,stop_switches";
  for (const ContactPairSpec& pair : ContactPairs()) out << ",switch_" << pair.name;
  for (int stop = 0; stop < kNumJointStops; ++stop) out << ",switch_stop_" << StopName(stop);
  out << '\n';
  const auto old_precision = out.precision(10);
  for (const TickProfile& t : Ticks()) {
    out << t.t << ',' << WalkingStateName(t.state) << ',' << t.steps << ',' << t.error_test_failures << ','
        << t.nonlinear_failures << ',' << t.step_sum / static_cast<double>(t.steps) << ',' << t.step_min << ','
        << t.step_max << ',' << t.max_order;
    for (long n : t.limiting) out << ',' << n;
    // what pushes at the tick's end: pairs joined by '+', springs, stops
    std::string pairs_on, stops_on;
    int springs_on = 0;
    for (int pair = 0; pair < kNumContactPairs; ++pair) {
      if (t.at_end.elements[pair] == 0) continue;
      pairs_on += (pairs_on.empty() ? "" : "+") + std::string(ContactPairs()[pair].name);
      springs_on += t.at_end.elements[pair];
    }
    for (int stop = 0; stop < kNumJointStops; ++stop) {
      if (t.at_end.stops[stop]) stops_on += (stops_on.empty() ? "" : "+") + std::string(StopName(stop));
    }
    out << ',' << pairs_on << ',' << springs_on << ',' << stops_on;
    out << ',' << t.PairSwitches() << ',' << t.spring_switches << ',' << t.StopSwitches();
    for (long n : t.pair_switches) out << ',' << n;
    for (long n : t.stop_switches) out << ',' << n;
    out << '\n';
  }
  out.precision(old_precision);
}

namespace {

// the totals of some ticks
nlohmann::ordered_json SummaryOf(const std::vector<const TickProfile*>& ticks) {
  using nlohmann::ordered_json;
  long steps = 0, error_tests = 0, nonlinear = 0, spring_switches = 0, ticks_with_pair_switch = 0,
       ticks_with_stop_switch = 0;
  double step_sum = 0, step_min = 0, step_max = 0;
  int max_order = 0;
  std::array<long, kNumStateComponents> limiting{};
  std::array<long, kNumContactPairs> pairs{};
  std::array<long, kNumJointStops> stops{};
  std::array<long, 6> orders{};  // ticks by their largest order (BDF: 1..5)
  std::vector<double> steps_per_tick;
  for (const TickProfile* t : ticks) {
    step_min = steps == 0 ? t->step_min : std::min(step_min, t->step_min);
    step_max = std::max(step_max, t->step_max);
    steps += t->steps;
    steps_per_tick.push_back(static_cast<double>(t->steps));
    error_tests += t->error_test_failures;
    nonlinear += t->nonlinear_failures;
    step_sum += t->step_sum;
    max_order = std::max(max_order, t->max_order);
    ++orders[std::clamp(t->max_order, 0, 5)];
    spring_switches += t->spring_switches;
    ticks_with_pair_switch += t->PairSwitches() > 0 ? 1 : 0;
    ticks_with_stop_switch += t->StopSwitches() > 0 ? 1 : 0;
    for (int i = 0; i < kNumStateComponents; ++i) limiting[i] += t->limiting[i];
    for (int i = 0; i < kNumContactPairs; ++i) pairs[i] += t->pair_switches[i];
    for (int i = 0; i < kNumJointStops; ++i) stops[i] += t->stop_switches[i];
  }
  const double n = static_cast<double>(std::max<size_t>(1, ticks.size()));
  std::sort(steps_per_tick.begin(), steps_per_tick.end());
  const auto quantile = [&](double p) {
    if (steps_per_tick.empty()) return 0.0;
    return steps_per_tick[static_cast<size_t>(std::floor(p * static_cast<double>(steps_per_tick.size() - 1)))];
  };
  ordered_json out;
  out["ticks"] = ticks.size();
  out["steps"] = steps;
  out["steps_per_tick"] = {{"mean", static_cast<double>(steps) / n},
                           {"median", quantile(0.5)},
                           {"p90", quantile(0.9)},
                           {"max", steps_per_tick.empty() ? 0.0 : steps_per_tick.back()}};
  out["error_test_failures"] = error_tests;
  out["nonlinear_failures"] = nonlinear;
  out["step"] = {{"mean", steps > 0 ? step_sum / static_cast<double>(steps) : 0.0}, {"min", step_min}, {"max", step_max}};
  out["max_order"] = max_order;
  ordered_json by_order;
  for (int q = 1; q <= 5; ++q) by_order[std::to_string(q)] = orders[q];
  out["ticks_by_max_order"] = by_order;
  // the limiting components, most frequent first, with their share of the steps
  std::array<int, kNumStateComponents> order{};
  for (int i = 0; i < kNumStateComponents; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return limiting[a] > limiting[b]; });
  ordered_json limits = ordered_json::object();
  for (int i : order) {
    if (limiting[i] > 0) limits[StateComponentNames()[i]] = limiting[i];
  }
  out["limiting"] = limits;
  long pair_total = 0, stop_total = 0;
  ordered_json pair_json = ordered_json::object(), stop_json = ordered_json::object();
  for (int i = 0; i < kNumContactPairs; ++i) {
    pair_total += pairs[i];
    if (pairs[i] > 0) pair_json[ContactPairs()[i].name] = pairs[i];
  }
  for (int i = 0; i < kNumJointStops; ++i) {
    stop_total += stops[i];
    if (stops[i] > 0) stop_json[StopName(i)] = stops[i];
  }
  out["pair_switches"] = {{"total", pair_total},
                          {"per_tick", static_cast<double>(pair_total) / n},
                          {"ticks_with_one", ticks_with_pair_switch},
                          {"by_pair", pair_json}};
  out["spring_switches"] = {{"total", spring_switches}, {"per_tick", static_cast<double>(spring_switches) / n}};
  out["stop_switches"] = {{"total", stop_total},
                          {"per_tick", static_cast<double>(stop_total) / n},
                          {"ticks_with_one", ticks_with_stop_switch},
                          {"by_stop", stop_json}};
  return out;
}

}  // namespace

nlohmann::ordered_json StepProfile::Summary() const {
  const std::vector<TickProfile> ticks = Ticks();
  std::vector<const TickProfile*> all;
  for (const TickProfile& t : ticks) all.push_back(&t);
  nlohmann::ordered_json out;
  out["all"] = SummaryOf(all);
  for (WalkingState s : kWalkingStates) {
    std::vector<const TickProfile*> in_state;
    for (const TickProfile* t : all) {
      if (t->state == s) in_state.push_back(t);
    }
    out[WalkingStateName(s)] = SummaryOf(in_state);
  }
  return out;
}

}  // namespace walkers
