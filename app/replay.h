// Pictures of a recorded walk (control/walk_record.h): a self-contained HTML
// animation and an SVG filmstrip.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace walkers::app {

// The viewer page with the walk embedded; no network needed to open it.
std::string ReplayHtml(const nlohmann::json& walk);

// Snapshots of the walker every `interval` seconds, drawn to scale at their
// positions along the ground.
std::string FilmstripSvg(const nlohmann::json& walk, double interval = 1.0);

}  // namespace walkers::app
