#include "control/walk_record.h"

#include <algorithm>

#include "control/start_pose.h"
#include "dynamics/energy.h"
#include "dynamics/kinematics.h"

namespace walkers {
namespace {

using nlohmann::json;

json Point(const Vec2& p) { return json::array({p.x(), p.y()}); }

// the points of one frame, appended to the frames' parallel arrays
void AppendPose(const Kinematics& kin, json* frames) {
  (*frames)["trunk"].push_back(json::array({kin.trunk.p.x(), kin.trunk.p.y(), kin.pitch.angle}));
  (*frames)["hip"].push_back(Point(kin.hip.p));
  const char* side[kNumLegs] = {"_l", "_r"};
  for (int leg = 0; leg < kNumLegs; ++leg) {
    const LegKinematics& l = kin.legs[leg];
    (*frames)[std::string("knee") + side[leg]].push_back(Point(l.knee.p));
    (*frames)[std::string("ankle") + side[leg]].push_back(Point(l.ankle.p));
    (*frames)[std::string("foot") + side[leg]].push_back(l.foot.angle);
  }
}

}  // namespace

json BodyJson(const Model& model) {
  const BodyParameters& b = model.body;
  return {{"half_body_x", b.half_body_x},   {"half_body_y", b.half_body_y},
          {"half_foot_x", b.half_foot_x},   {"half_foot_y", b.half_foot_y},
          {"femur_length", b.femur_length}, {"tibia_length", b.tibia_length},
          {"knee_radius", model.contact.knee_radius}};
}

json StartPoseJson(const Genome& genome) {
  const Model model = BuildModel(BodyOf(genome));
  const State start = StartState(model);
  Kinematics kin;
  ComputeKinematics(model, start.q, start.v, &kin);
  json frame = json::object();
  AppendPose(kin, &frame);
  json pose = json::object();
  for (const auto& item : frame.items()) pose[item.key()] = item.value().front();
  return pose;
}

RecordedWalk RecordWalk(const Genome& genome, const Preset& preset, const std::string& title,
                        const EvaluationSettings& settings) {
  const Model model = BuildModel(BodyOf(genome), ModelOptions{}, settings.contact, settings.weld);
  json frames = json::object();
  const TickObserver observer = [&](double t, const State& state, const WalkingController& controller) {
    Kinematics kin;
    ComputeKinematics(model, state.q, state.v, &kin);
    frames["t"].push_back(t);
    frames["state"].push_back(WalkingStateName(controller.state()));
    frames["x_target"].push_back(controller.x_target());
    AppendPose(kin, &frames);
    frames["planted_l"].push_back(controller.inputs().welds[kLeft].active);
    frames["planted_r"].push_back(controller.inputs().welds[kRight].active);
    frames["distance"].push_back(std::min(kin.legs[kLeft].ankle.p.x(), kin.legs[kRight].ankle.p.x()));
    const CenterOfMass com = ComputeCenterOfMass(model, kin);
    frames["com"].push_back(Point(com.p));
    frames["com_velocity"].push_back(Point(com.v));
  };
  RecordedWalk out;
  out.result = Evaluate(genome, preset, settings, observer);
  out.json = {{"title", title},
              {"fitness", out.result.fitness},
              {"gait", GaitName(out.result.gait)},
              {"leg_length", out.result.leg_length},
              {"preset", preset.name},
              {"body", BodyJson(model)},
              {"frames", frames}};
  return out;
}

}  // namespace walkers
