// Layered textures: parsing into Texture::layersBelow, the transformation
// after the textures moving every layer, and what the layers let through.
#include <gtest/gtest.h>

#include "sdl/interpreter.h"

using namespace frameray;
using namespace frameray::scene;

namespace {

struct Quiet : sdl::MessageSink {
    void message(sdl::Stream, const std::string&) override {}
};

struct Parsed {
    sdl::FrameContext ctx;
    sdl::TokenCache cache;
    Quiet sink;
    sdl::Interpreter interp{ctx, cache, sink};
    Scene scene;
    explicit Parsed(const std::string& text) { scene = interp.parseText("t.pov", text); }
};

}  // namespace

TEST(TextureLayers, ConsecutiveTexturesStackNearestFirst) {
    Parsed p(R"(
sphere { 0, 1
  texture { pigment { rgb <1, 0, 0> } }
  texture { pigment { rgbf <0, 1, 0, 0.5> } }
  texture { pigment { rgbt <0, 0, 1, 0.5> } }
  translate x
})");
    ASSERT_EQ(p.scene.objects.size(), 1u);
    const Texture& top = *p.scene.objects[0]->texture;
    ASSERT_EQ(top.layersBelow.size(), 2u);
    EXPECT_DOUBLE_EQ(top.pigment->solidColor().rgb.b, 1.0);
    EXPECT_DOUBLE_EQ(top.layersBelow[0]->pigment->solidColor().rgb.g, 1.0);
    EXPECT_DOUBLE_EQ(top.layersBelow[1]->pigment->solidColor().rgb.r, 1.0);
    // The translation after the textures moves every layer.
    for (const auto& layer : top.layersBelow)
        EXPECT_DOUBLE_EQ(layer->transform.inversePoint(Vec3(1, 0, 0)).x, 0.0);
    // The opaque bottom layer stops shadow rays.
    EXPECT_TRUE(top.throughAt(Vec3(1, 0, 0)).isBlack());
}

TEST(TextureLayers, ThroughIsTheProductOfTheLayers) {
    Parsed p(R"(
sphere { 0, 1
  texture { pigment { rgbf <1, 0.5, 0.2, 0.8> } }
  texture { pigment { rgbt <0, 0, 1, 0.5> } }
})");
    const RGB through = p.scene.objects[0]->texture->throughAt(Vec3(0, 0, 0));
    EXPECT_NEAR(through.r, 0.5 * 0.8, 1e-6);
    EXPECT_NEAR(through.g, 0.5 * 0.4, 1e-6);
    EXPECT_NEAR(through.b, 0.5 * 0.16, 1e-6);
}

TEST(TextureLayers, OpaquePigmentsAreKnownWithoutEvaluating) {
    // Pigments whose every colour has filter and transmit 0 let nothing
    // through wherever a shadow ray meets them; one such layer blacks out
    // the whole stack.
    Parsed p(R"(
#declare Clear = color_map { [0 rgb 1] [0.5 rgbf <1, 0, 0, 0.6>] [1 rgb 0] }
sphere { 0, 1 pigment { rgb <1, 0.5, 0> } }
sphere { 0, 1 pigment { rgbf <1, 0.5, 0, 0.2> } }
sphere { 0, 1 pigment { bozo color_map { [0 rgb 1] [1 rgb <0, 0.2, 0>] } } }
sphere { 0, 1 pigment { bozo color_map { Clear } } }
sphere { 0, 1 pigment { checker rgb 1 rgb 0 } }
sphere { 0, 1 pigment { checker rgb 1 rgbt 0.5 } }
sphere { 0, 1 pigment { gradient x pigment_map { [0 rgb 1] [1 checker rgb 0 rgb 1] } } }
sphere { 0, 1 pigment { gradient x pigment_map { [0 rgb 1] [1 bozo color_map { Clear }] } } }
sphere { 0, 1
  texture { pigment { granite color_map { [0 rgb 1] [1 rgb 0.5] } } }
  texture { pigment { bozo color_map { Clear } } }
})");
    ASSERT_EQ(p.scene.objects.size(), 9u);
    const bool expected[] = {true, false, true, false, true, false, true, false};
    for (size_t i = 0; i < 8; ++i)
        EXPECT_EQ(p.scene.objects[i]->texture->pigment->alwaysOpaque(), expected[i]) << i;
    const Texture& stack = *p.scene.objects[8]->texture;
    ASSERT_EQ(stack.layersBelow.size(), 1u);
    EXPECT_FALSE(stack.pigment->alwaysOpaque());
    EXPECT_TRUE(stack.layersBelow[0]->pigment->alwaysOpaque());
    // Black wherever the clear top layer is evaluated.
    for (double x = -1; x <= 1; x += 0.05)
        EXPECT_TRUE(stack.throughAt(Vec3(x, 0.3 * x, 0.1)).isBlack()) << x;
    // The clear layer alone lets light through somewhere.
    bool passes = false;
    for (double x = -1; x <= 1; x += 0.05)
        passes = passes || !p.scene.objects[3]->texture->throughAt(Vec3(x, 0.3 * x, 0.1)).isBlack();
    EXPECT_TRUE(passes);
}
