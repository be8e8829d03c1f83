// A walk recorded for people: every 30 Hz frame of one evaluation as the
// points of the walker, in the JSON that the replay viewer
// (app/replay_template.html) and the statistics package's figures (scripts/walkers_stats/figures.py) read.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "control/evaluation.h"

namespace walkers {

// {"title", "fitness", "gait", "leg_length", "preset", "body": {...},
//  "frames": {"t", "state", "x_target", "trunk", "hip", "knee_l", "ankle_l",
//  "foot_l", "knee_r", "ankle_r", "foot_r", "planted_l", "planted_r",
//  "distance", "com", "com_velocity"}}
struct RecordedWalk {
  EvaluationResult result;
  nlohmann::json json;
};
RecordedWalk RecordWalk(const Genome& genome, const Preset& preset, const std::string& title,
                        const EvaluationSettings& settings = {});

// The body sizes the drawings need: {"half_body_x", ..., "knee_radius"}.
nlohmann::json BodyJson(const Model& model);

// The walker standing at the start, as the points of one frame:
// {"trunk": [x, y, pitch], "hip", "knee_l", "ankle_l", "foot_l", ...}.
nlohmann::json StartPoseJson(const Genome& genome);

}  // namespace walkers
