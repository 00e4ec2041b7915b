#include <array>
#include <cstdint>
#include <sstream>

#include "core/geometry/planar.hpp"
#include "core/world/export_format.hpp"
#include "core/world/world_export.hpp"
#include "core/world/xml_reader.hpp"

namespace socsim::world {

namespace {

// Same type, same colour, in every drawing (FNV-1a of the type into a fixed pastel palette).
std::string zone_colour(const std::string& type) {
  static constexpr std::array<const char*, 12> kPalette = {"#f4d6a0", "#bcd8ee", "#c9e4c5", "#f2c4ce",
                                                           "#d9c8ec", "#f7e8a4", "#bfe3df", "#e8cfb5",
                                                           "#d0d7e1", "#e6e0c0", "#c6d8b0", "#eac0a8"};
  std::uint32_t h = 2166136261u;
  for (const char c : type) h = (h ^ static_cast<unsigned char>(c)) * 16777619u;
  return kPalette[h % kPalette.size()];
}

std::string points(const std::vector<Point>& ring) {
  std::string out;
  for (const Point& p : ring) {
    if (!out.empty()) out += ' ';
    out += micro(p.x);
    out += ',';
    out += micro(-p.y);
  }
  return out;
}

}  // namespace

std::string export_svg(const World& world, const SvgOptions& options) {
  const geometry::Box b = world.bounds();
  const double margin = 1.0;
  const double w = b.width() + 2 * margin;
  const double h = b.height() + 2 * margin;
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << micro(b.min.x - margin) << " "
    << micro(-b.max.y - margin) << " " << micro(w) << " " << micro(h) << "\" width=\""
    << micro(w * options.pixels_per_metre) << "\" height=\"" << micro(h * options.pixels_per_metre)
    << "\">\n";
  o << "  <title>" << xml_escape(world.name().empty() ? "socsim world" : world.name()) << "</title>\n";
  o << "  <g id=\"zones\" stroke=\"none\">\n";
  for (const auto& z : world.zones()) {
    o << "    <polygon id=\"zone-" << xml_escape(z.name) << "\" class=\"zone " << xml_escape(z.type)
      << "\" fill=\"" << zone_colour(z.type) << "\" points=\"" << points(z.polygon.outer) << "\"/>\n";
  }
  o << "  </g>\n  <g id=\"rois\" fill=\"none\" stroke=\"#7a5195\" stroke-width=\"0.05\" "
       "stroke-dasharray=\"0.2 0.1\">\n";
  for (const auto& r : world.rois()) {
    o << "    <polygon id=\"roi-" << xml_escape(r.name) << "\" class=\"roi " << xml_escape(r.kind)
      << "\" points=\"" << points(r.polygon.outer) << "\"/>\n";
  }
  o << "  </g>\n  <g id=\"walls\" stroke=\"#333333\" stroke-width=\"0.12\" stroke-linecap=\"square\">\n";
  for (const auto& wall : world.walls()) {
    o << "    <line x1=\"" << micro(wall.segment.a.x) << "\" y1=\"" << micro(-wall.segment.a.y) << "\" x2=\""
      << micro(wall.segment.b.x) << "\" y2=\"" << micro(-wall.segment.b.y) << "\"/>\n";
  }
  o << "  </g>\n  <g id=\"doors\" stroke=\"#2a9d8f\" stroke-width=\"0.16\">\n";
  for (const auto& d : world.doors()) {
    o << "    <line id=\"door-" << xml_escape(d.name) << "\" x1=\"" << micro(d.opening.a.x) << "\" y1=\""
      << micro(-d.opening.a.y) << "\" x2=\"" << micro(d.opening.b.x) << "\" y2=\"" << micro(-d.opening.b.y)
      << "\"/>\n";
  }
  o << "  </g>\n  <g id=\"entities\" fill=\"#e76f51\">\n";
  for (const auto& e : world.entities()) {
    o << "    <circle id=\"entity-" << xml_escape(e.name) << "\" class=\"entity " << xml_escape(e.type)
      << "\" cx=\"" << micro(e.pose.x) << "\" cy=\"" << micro(-e.pose.y) << "\" r=\"0.2\"/>\n";
  }
  o << "  </g>\n";
  if (options.labels) {
    o << "  <g id=\"labels\" font-family=\"sans-serif\" text-anchor=\"middle\" fill=\"#222222\">\n";
    for (const auto& z : world.zones()) {
      const Point c = geometry::centroid(z.polygon.outer);
      o << "    <text x=\"" << micro(c.x) << "\" y=\"" << micro(-c.y) << "\" font-size=\"0.5\">"
        << xml_escape(z.name) << "</text>\n";
    }
    for (const auto& r : world.rois()) {
      const Point c = geometry::centroid(r.polygon.outer);
      o << "    <text x=\"" << micro(c.x) << "\" y=\"" << micro(-c.y + 0.45)
        << "\" font-size=\"0.3\" fill=\"#7a5195\">" << xml_escape(r.name) << "</text>\n";
    }
    for (const auto& e : world.entities()) {
      o << "    <text x=\"" << micro(e.pose.x) << "\" y=\"" << micro(-e.pose.y - 0.3)
        << "\" font-size=\"0.25\">" << xml_escape(e.name) << "</text>\n";
    }
    o << "  </g>\n";
  }
  o << "</svg>\n";
  return o.str();
}

}  // namespace socsim::world
