#include "app/replay.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace walkers::app {

extern const char kReplayTemplate[];

namespace {

using nlohmann::json;

constexpr const char* kPlaceholder = "/*WALKER_DATA*/null";

// a JSON text that cannot end the <script> element it is embedded in
std::string ScriptSafe(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') {
      out += "<\\/";
      ++i;
    } else {
      out += text[i];
    }
  }
  return out;
}

// text that cannot end or open an XML element
std::string XmlEscaped(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return out;
}

struct Xy {
  double x, y;
};
Xy At(const json& point) { return {point[0].get<double>(), point[1].get<double>()}; }

// corners of a box of half sizes (hx, hy) at c turned by a
std::string BoxPoints(Xy c, double hx, double hy, double a, double scale, double x0, double y_ground) {
  std::ostringstream s;
  const double ca = std::cos(a), sa = std::sin(a);
  const double corners[4][2] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
  for (const auto& k : corners) {
    const double x = c.x + ca * k[0] - sa * k[1], y = c.y + sa * k[0] + ca * k[1];
    s << (x - x0) * scale << ',' << y_ground - y * scale << ' ';
  }
  return s.str();
}

}  // namespace

std::string ReplayHtml(const json& walk) {
  std::string page = kReplayTemplate;
  const std::size_t at = page.find(kPlaceholder);
  if (at == std::string::npos) throw std::runtime_error("the replay template has no data placeholder");
  page.replace(at, std::string(kPlaceholder).size(), ScriptSafe(walk.dump()));
  return page;
}

std::string FilmstripSvg(const json& walk, double interval) {
  const json& f = walk.at("frames");
  const json& b = walk.at("body");
  const double hx = b.at("half_body_x"), hy = b.at("half_body_y");
  const double fx = b.at("half_foot_x"), fy = b.at("half_foot_y");
  const std::size_t n = f.at("t").size();
  if (n == 0) throw std::runtime_error("the walk has no frames");

  // the frames to draw: one per interval, and the last
  std::vector<std::size_t> shots;
  double next = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (f["t"][i].get<double>() + 1e-9 < next && i + 1 != n) continue;
    shots.push_back(i);
    next += interval;
  }
  // one panel per frame, centred on the trunk, all at one scale
  double half_width = 0.0, height_m = 0.0;
  for (std::size_t i : shots) {
    const double cx = At(f["trunk"][i]).x, reach = std::hypot(hx, hy);
    for (const char* p : {"hip", "knee_l", "knee_r", "ankle_l", "ankle_r"}) {
      half_width = std::max(half_width, std::abs(At(f[p][i]).x - cx) + fx);
      height_m = std::max(height_m, At(f[p][i]).y);
    }
    half_width = std::max(half_width, reach);
    height_m = std::max(height_m, At(f["trunk"][i]).y + reach);
  }
  const double scale = std::clamp(90.0 / std::max(half_width, height_m / 2.0), 20.0, 200.0);  // px per metre
  const double panel_w = 2.0 * (half_width + 0.15) * scale, panel_h = (height_m + 0.2) * scale + 36.0;
  const int columns = std::min<int>(8, static_cast<int>(shots.size()));
  const int rows = (static_cast<int>(shots.size()) + columns - 1) / columns;
  const double width = columns * panel_w, height = rows * panel_h + 28.0;

  std::ostringstream svg;
  svg << R"(<svg xmlns="http://www.w3.org/2000/svg" width=")" << width << R"(" height=")" << height
      << R"(" viewBox="0 0 )" << width << ' ' << height << R"(" font-family="sans-serif" font-size="12">)" << '\n';
  svg << R"(<rect width="100%" height="100%" fill="white"/>)" << '\n';
  const char* colours[2] = {"#1f77b4", "#d62728"};
  const char* side[2] = {"_l", "_r"};
  const char* leg_names[2] = {"left leg", "right leg"};
  svg << "<text x=\"8\" y=\"18\" font-size=\"14\">" << XmlEscaped(walk.value("title", std::string("walker")))
      << " (fitness " << walk.value("fitness", 0.0) << ", " << XmlEscaped(walk.value("gait", std::string("?")))
      << "); ticks every 0.5 m; ";
  for (int leg = 0; leg < 2; ++leg) {
    svg << (leg ? ", " : "") << "<tspan fill=\"" << colours[leg] << "\" font-weight=\"bold\">" << leg_names[leg]
        << "</tspan>";
  }
  svg << "</text>\n";
  for (std::size_t k = 0; k < shots.size(); ++k) {
    const std::size_t i = shots[k];
    const double left = (k % columns) * panel_w, top = 28.0 + (k / columns) * panel_h;
    const double cx = At(f["trunk"][i]).x;
    const double x0 = cx - panel_w / 2.0 / scale;  // world x at the panel's left edge
    const double ground = top + (height_m + 0.2) * scale;
    auto px = [&](Xy p) {
      return std::to_string(left + (p.x - x0) * scale) + "," + std::to_string(ground - p.y * scale);
    };
    svg << "<g>\n<line x1=\"" << left + 4 << "\" y1=\"" << ground << "\" x2=\"" << left + panel_w - 4 << "\" y2=\""
        << ground << "\" stroke=\"#444\" stroke-width=\"2\"/>\n";
    for (double x = std::ceil(x0 * 2.0) / 2.0; (x - x0) * scale <= panel_w - 4; x += 0.5) {
      svg << "<line x1=\"" << left + (x - x0) * scale << "\" y1=\"" << ground << "\" x2=\"" << left + (x - x0) * scale
          << "\" y2=\"" << ground + 5 << "\" stroke=\"#444\"/>\n";
    }
    const json& t = f["trunk"][i];
    svg << "<polygon points=\"" << BoxPoints({t[0], t[1]}, hx, hy, t[2], scale, x0 - left / scale, ground)
        << "\" fill=\"#8e7cc3\" stroke=\"#333\"/>\n";
    for (int leg = 0; leg < 2; ++leg) {
      const Xy hip = At(f["hip"][i]), knee = At(f[std::string("knee") + side[leg]][i]),
               ankle = At(f[std::string("ankle") + side[leg]][i]);
      svg << "<polyline points=\"" << px(hip) << ' ' << px(knee) << ' ' << px(ankle) << "\" fill=\"none\" stroke=\""
          << colours[leg] << "\" stroke-width=\"3\"/>\n";
      svg << "<polygon points=\""
          << BoxPoints(ankle, fx, fy, f[std::string("foot") + side[leg]][i], scale, x0 - left / scale, ground)
          << "\" fill=\"" << colours[leg] << "\" fill-opacity=\"0.5\" stroke=\"#333\"/>\n";
    }
    svg << "<text x=\"" << left + panel_w / 2 << "\" y=\"" << ground + 20 << "\" text-anchor=\"middle\">t = "
        << std::round(f["t"][i].get<double>() * 10.0) / 10.0 << " s, x = " << std::round(cx * 100.0) / 100.0
        << " m</text>\n</g>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace walkers::app
