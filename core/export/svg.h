// SVG drawings: a document of filled polygons, polylines, circles and text in math coordinates
// (y up), written as SVG text. The one place that knows SVG syntax; text is XML-escaped.
//
// In:  the drawing's extent in math coordinates and its width in pixels; the shapes.
// Out: the SVG text (str()).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace tessera {

struct SvgPoint {
  double x = 0, y = 0;
};

struct SvgStyle {
  std::string fill = "none";  // an SVG colour, "#rrggbb" or a name
  std::string stroke = "none";
  double stroke_width = 0;  // in pixels
};

// "&", "<", ">", quotes -> entities; bytes below 0x20 other than tab and newline -> "?".
std::string escape_xml(std::string_view text);

// "#rrggbb" of a colour given by hue, saturation and lightness in [0, 1].
std::string hsl_colour(double hue, double saturation, double lightness);

class SvgDocument {
 public:
  // The rectangle [min_x, max_x] x [min_y, max_y] drawn `width_px` pixels wide.
  SvgDocument(double min_x, double min_y, double max_x, double max_y, double width_px);

  void title(std::string_view text);
  void polygon(const std::vector<SvgPoint>& points, const SvgStyle& style);
  void polyline(const std::vector<SvgPoint>& points, const SvgStyle& style);
  void circle(SvgPoint centre, double radius, const SvgStyle& style);
  // Text centred at `at`, `size_px` high.
  void text(SvgPoint at, std::string_view text, double size_px, const std::string& colour);

  std::string str() const;

 private:
  void points(const std::vector<SvgPoint>& points);
  void style(const SvgStyle& style);
  void number(double pixels);
  double px(double x) const;
  double py(double y) const;

  double min_x_, max_y_, scale_, width_px_, height_px_;
  std::string title_;
  std::string body_;
};

}  // namespace tessera
