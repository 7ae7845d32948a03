// `colonosim render` after an unsteered push: whole simulated insertions
// through the CLI, so labelled slow (tests/CMakeLists.txt): they run in
// `./setup.sh test`, not under the sanitizers, where the procedure loop runs
// about 33 times slower.

#include "../cli/RunColonosim.h"

#include <QImage>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace {

using colonosim::testing::runColonosim;

// The command pushes straight in without steering. On a tortuous generated
// colon the lens ends at the wall or through it, and no picture is left
// black without a word: a lens at the wall is red-out (as the recording has
// it), and a tip pushed more than a scope diameter into the wall is said,
// with how far. (On this case, at 550 mm the lens is at the wall, 0.6 mm
// into it, and at 600 mm the tip is 56 mm through.) One test a depth: each
// push is a whole simulated insertion, and the two run side by side.
struct UnsteeredPush {
    bool redOut = false;
    bool said = false;
    double meanRed = 0.0;
    std::string output;
};

UnsteeredPush pushUnsteered(int millimetres)
{
    const std::filesystem::path dir(COLONOSIM_TEST_ARTEFACTS);
    std::filesystem::create_directories(dir);
    const auto caseFile = dir / ("cli_tortuous_case_" + std::to_string(millimetres) + ".xml");
    auto r = runColonosim("case generate --seed 2 --require \"boston<=3\" --out " + caseFile.string());
    EXPECT_EQ(r.status, 0) << r.output;
    const auto png = dir / ("cli_pushed_" + std::to_string(millimetres) + ".png");
    r = runColonosim("render --case " + caseFile.string() + " --insertion-mm " + std::to_string(millimetres) +
                     " --out " + png.string());
    EXPECT_EQ(r.status, 0) << r.output;
    UnsteeredPush push;
    push.output = r.output;
    push.redOut = r.output.find("red-out 1\n") != std::string::npos;
    push.said = r.output.find("mm into the wall (more than the scope's 13 mm diameter)") != std::string::npos;
    const QImage image(QString::fromStdString(png.string()));
    EXPECT_FALSE(image.isNull()) << png;
    if (image.isNull()) {
        return push;
    }
    double sum = 0.0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            sum += qRed(image.pixel(x, y));
        }
    }
    push.meanRed = sum / (image.width() * image.height());
    return push;
}

TEST(RenderCli, AnUnsteeredPushAgainstTheWallIsRedOutNotABlackPicture)
{
    const UnsteeredPush push = pushUnsteered(550);
    EXPECT_TRUE(push.redOut || push.said) << "the scenario: the lens ends at the wall: " << push.output;
    EXPECT_TRUE(push.meanRed > 20.0 || push.said)
        << "a black picture (mean red " << push.meanRed << ") and no word why: " << push.output;
}

TEST(RenderCli, AnUnsteeredPushThroughTheWallIsSaidWithHowFar)
{
    const UnsteeredPush push = pushUnsteered(600);
    ASSERT_TRUE(push.said) << "the scenario: the tip ends more than a diameter through the wall: "
                           << push.output;
    const std::string lead = "has carried the tip ";
    const size_t at = push.output.find(lead);
    ASSERT_NE(at, std::string::npos) << push.output;
    EXPECT_GT(std::stod(push.output.substr(at + lead.size())), 13.0) << "how far, in mm: " << push.output;
}

}  // namespace
