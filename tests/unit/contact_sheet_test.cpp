// The contact sheet's page and grid (anim/contact_sheet.h, issue 29) and
// the thumbnails' shrinking (anim/frame_pixels.h).
#include "anim/contact_sheet.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "anim/frame_pixels.h"
#include "options/render_options.h"

using namespace frameray;

namespace {

anim::SheetFrame frame(int number, anim::SheetFrame::State state) {
    anim::SheetFrame f;
    f.number = number;
    f.clock = number * 0.25;
    f.file = "shot" + std::to_string(number) + ".png";
    f.state = state;
    return f;
}

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST(ContactSheet, PageListsEveryFrameWithItsFigures) {
    anim::SheetFrame a = frame(1, anim::SheetFrame::State::Rendered);
    a.seconds = 1.5;
    a.rays = 1234567;
    a.thumbnailPng = "\x89PNG";  // the bytes go in as base64
    anim::SheetFrame b = frame(2, anim::SheetFrame::State::Failed);
    b.failure = "error: <bad> \"thing\"";
    const anim::SheetFrame c = frame(3, anim::SheetFrame::State::Pending);
    anim::SheetFrame d = frame(4, anim::SheetFrame::State::Kept);
    d.thumbnailPng = "abcd";
    const std::string page = anim::contactSheetHtml("shot", {a, b, c, d}, 12);
    EXPECT_EQ(count(page, "<div class=\"cell "), 4u);
    EXPECT_NE(page.find("<h1>shot: 2 of 4 frames, 1 failed</h1>"), std::string::npos);
    EXPECT_NE(page.find("frame 1 &middot; clock 0.25<br>1.50 s &middot; 1 234 567 rays"),
              std::string::npos);
    EXPECT_NE(page.find("src=\"data:image/png;base64,iVBORw==\""), std::string::npos);
    EXPECT_NE(page.find("src=\"data:image/png;base64,YWJjZA==\""), std::string::npos);
    // The failure is escaped into the cell's tooltip and the cell marked.
    EXPECT_NE(page.find("class=\"cell failed\""), std::string::npos);
    EXPECT_NE(page.find("title=\"error: &lt;bad&gt; &quot;thing&quot;\""), std::string::npos);
    EXPECT_NE(page.find("not rendered yet"), std::string::npos);
    EXPECT_NE(page.find("kept (an earlier run)"), std::string::npos);
    EXPECT_NE(page.find("const fps = 12;"), std::string::npos);
    EXPECT_NE(page.find("{n:4,clock:\"1\",file:\"shot4.png\",state:\"kept\",browser:true}"),
              std::string::npos);
    // Self-contained: nothing is fetched from a network.
    EXPECT_EQ(page.find("http"), std::string::npos);
}

TEST(ContactSheet, ScriptDataCannotCloseTheScript) {
    anim::SheetFrame a = frame(1, anim::SheetFrame::State::Rendered);
    a.file = "a</script>b.png";
    const std::string page = anim::contactSheetHtml("x", {a}, 24);
    EXPECT_EQ(count(page, "</script>"), 1u);
}

TEST(ContactSheet, GridPlacesThumbnailsAndMarksFailures) {
    anim::SheetFrame a = frame(1, anim::SheetFrame::State::Rendered);
    a.thumbnail.width = 2;
    a.thumbnail.height = 1;
    a.thumbnail.rgb = {255, 255, 255, 10, 20, 30};
    const anim::SheetFrame b = frame(2, anim::SheetFrame::State::Failed);
    const anim::SheetFrame c = frame(3, anim::SheetFrame::State::Pending);
    const anim::Rgb8Image grid = anim::contactSheetGrid({a, b, c}, 2);
    // 2 columns of 2-pixel cells, 2 rows of 1-pixel cells, 4-pixel gaps.
    EXPECT_EQ(grid.width, 2 * (2 + 4) + 4);
    EXPECT_EQ(grid.height, 2 * (1 + 4) + 4);
    const auto at = [&](int x, int y, int c) {
        return grid.rgb[(static_cast<size_t>(y) * grid.width + x) * 3 + c];
    };
    EXPECT_EQ(at(4, 4, 0), 255);
    EXPECT_EQ(at(5, 4, 2), 30);
    EXPECT_EQ(at(10, 4, 0), 200);  // failed: red
    EXPECT_EQ(at(10, 4, 1), 30);
    EXPECT_EQ(at(4, 9, 0), at(4, 9, 1));  // missing: grey
    EXPECT_NE(at(4, 9, 0), at(0, 0, 0));  // ... not the background
}

TEST(FramePixels, ShrinkAveragesWholePixelsAndNeverEnlarges) {
    anim::Rgb8Image image;
    image.width = 4;
    image.height = 2;
    image.rgb.assign(4 * 2 * 3, 0);
    for (int x = 0; x < 2; ++x)
        for (int y = 0; y < 2; ++y)
            for (int c = 0; c < 3; ++c) image.rgb[(y * 4 + x) * 3 + c] = 200;
    const anim::Rgb8Image half = anim::shrinkToFit(image, 2, 2);
    ASSERT_EQ(half.width, 2);
    ASSERT_EQ(half.height, 1);
    EXPECT_EQ(half.rgb[0], 200);
    EXPECT_EQ(half.rgb[3], 0);
    const anim::Rgb8Image same = anim::shrinkToFit(image, 160, 120);
    EXPECT_EQ(same.width, 4);
    EXPECT_EQ(same.rgb, image.rgb);
}

TEST(FramePixels, FileValuesToBytes) {
    image::EncodedImage file;
    file.width = 2;
    file.height = 1;
    file.channels = 1;
    file.values = {0.5f, 2.0f};
    const anim::Rgb8Image rgb = anim::rgb8Of(file);
    EXPECT_EQ(rgb.rgb, (std::vector<std::uint8_t>{128, 128, 128, 255, 255, 255}));
}
