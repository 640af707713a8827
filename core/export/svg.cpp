#include "export/svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tessera {

std::string escape_xml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        // XML 1.0 forbids most control characters even as entities.
        out += (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n') ? '?' : c;
    }
  }
  return out;
}

std::string hsl_colour(double hue, double saturation, double lightness) {
  const double c = (1 - std::abs(2 * lightness - 1)) * saturation;
  const double h = (hue - std::floor(hue)) * 6;
  const double x = c * (1 - std::abs(std::fmod(h, 2.0) - 1));
  const double m = lightness - c / 2;
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(h)) {
    case 0:
      r = c, g = x;
      break;
    case 1:
      r = x, g = c;
      break;
    case 2:
      g = c, b = x;
      break;
    case 3:
      g = x, b = c;
      break;
    case 4:
      r = x, b = c;
      break;
    default:
      r = c, b = x;
      break;
  }
  char hex[8];
  const auto byte = [m](double v) {
    return std::clamp(static_cast<int>(std::lround((v + m) * 255)), 0, 255);
  };
  std::snprintf(hex, sizeof hex, "#%02x%02x%02x", byte(r), byte(g), byte(b));
  return hex;
}

SvgDocument::SvgDocument(double min_x, double min_y, double max_x, double max_y, double width_px)
    : min_x_(min_x),
      max_y_(max_y),
      scale_(width_px / (max_x - min_x)),
      width_px_(width_px),
      height_px_(width_px / (max_x - min_x) * (max_y - min_y)) {}

double SvgDocument::px(double x) const {
  return (x - min_x_) * scale_;
}
double SvgDocument::py(double y) const {
  return (max_y_ - y) * scale_;
}

void SvgDocument::number(double pixels) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", pixels);
  body_ += text;
}

void SvgDocument::points(const std::vector<SvgPoint>& points) {
  body_ += " points=\"";
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i) body_ += ' ';
    number(px(points[i].x));
    body_ += ',';
    number(py(points[i].y));
  }
  body_ += '"';
}

void SvgDocument::style(const SvgStyle& style) {
  body_ += " fill=\"" + escape_xml(style.fill) + "\" stroke=\"" + escape_xml(style.stroke) + "\"";
  if (style.stroke != "none") {
    body_ += " stroke-width=\"";
    number(style.stroke_width);
    body_ += "\" stroke-linejoin=\"round\"";
  }
}

void SvgDocument::title(std::string_view text) {
  title_ = escape_xml(text);
}

void SvgDocument::polygon(const std::vector<SvgPoint>& pts, const SvgStyle& s) {
  body_ += "<polygon";
  points(pts);
  style(s);
  body_ += "/>\n";
}

void SvgDocument::polyline(const std::vector<SvgPoint>& pts, const SvgStyle& s) {
  body_ += "<polyline";
  points(pts);
  style(s);
  body_ += "/>\n";
}

void SvgDocument::circle(SvgPoint centre, double radius, const SvgStyle& s) {
  body_ += "<circle cx=\"";
  number(px(centre.x));
  body_ += "\" cy=\"";
  number(py(centre.y));
  body_ += "\" r=\"";
  number(radius * scale_);
  body_ += '"';
  style(s);
  body_ += "/>\n";
}

void SvgDocument::text(SvgPoint at, std::string_view content, double size_px,
                       const std::string& colour) {
  body_ += "<text x=\"";
  number(px(at.x));
  body_ += "\" y=\"";
  number(py(at.y));
  body_ += "\" font-size=\"";
  number(size_px);
  body_ +=
      "\" font-family=\"sans-serif\" text-anchor=\"middle\" dominant-baseline=\"central\" "
      "fill=\"" +
      escape_xml(colour) + "\">" + escape_xml(content) + "</text>\n";
}

std::string SvgDocument::str() const {
  char header[256];
  std::snprintf(header, sizeof header,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
                "viewBox=\"0 0 %.2f %.2f\">\n",
                width_px_, height_px_, width_px_, height_px_);
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += header;
  if (!title_.empty()) out += "<title>" + title_ + "</title>\n";
  out += body_;
  out += "</svg>\n";
  return out;
}

}  // namespace tessera
