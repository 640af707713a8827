// The SVG writer: escaping, coordinates (y up), colours.
#include <gtest/gtest.h>

#include "export/svg.h"

namespace tessera {
namespace {

TEST(Svg, EscapesText) {
  EXPECT_EQ(escape_xml("R2.4' <{5,10}> & \"x\""), "R2.4&apos; &lt;{5,10}&gt; &amp; &quot;x&quot;");
  EXPECT_EQ(escape_xml(std::string("a\0b\x01", 4)), "a?b?");
}

TEST(Svg, MapsMathCoordinatesToPixels) {
  SvgDocument svg(-1, -1, 1, 1, 200);
  svg.title("t<1>");
  svg.polygon({{-1, 1}, {1, 1}, {0, -1}}, {"#ff0000", "none", 0});
  svg.text({0, 0}, "a&b", 10, "#000000");
  const std::string text = svg.str();
  EXPECT_EQ(text.rfind("<?xml", 0), 0u);
  EXPECT_NE(text.find("viewBox=\"0 0 200.00 200.00\""), std::string::npos) << text;
  EXPECT_NE(text.find("<title>t&lt;1&gt;</title>"), std::string::npos) << text;
  EXPECT_NE(text.find("points=\"0.00,0.00 200.00,0.00 100.00,200.00\""), std::string::npos) << text;
  EXPECT_NE(text.find(">a&amp;b</text>"), std::string::npos) << text;
  EXPECT_EQ(text.substr(text.size() - 7), "</svg>\n");
}

TEST(Svg, HslColours) {
  EXPECT_EQ(hsl_colour(0, 1, 0.5), "#ff0000");
  EXPECT_EQ(hsl_colour(1.0 / 3, 1, 0.5), "#00ff00");
  EXPECT_EQ(hsl_colour(0.5, 0, 1), "#ffffff");
}

}  // namespace
}  // namespace tessera
