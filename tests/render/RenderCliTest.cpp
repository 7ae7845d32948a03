// `colonosim render` as a person or a script uses it: exit 2 with the field,
// value and allowed range on bad input; PNG files of the asked size otherwise.

#include "../cli/RunColonosim.h"

#include <QImage>

#include <gtest/gtest.h>

#include <filesystem>
#include <ostream>
#include <string>

namespace {

using colonosim::testing::runColonosim;

struct BadArguments {
    const char* name;
    const char* arguments;
    const char* mentions;  ///< the message must name the field and range
    const char* range;
};

void PrintTo(const BadArguments& bad, std::ostream* out)
{
    *out << bad.name;
}

class RenderCliBadArguments : public ::testing::TestWithParam<BadArguments> {};

TEST_P(RenderCliBadArguments, ExitTwoNamingFieldValueAndRange)
{
    const BadArguments& bad = GetParam();
    const auto r = runColonosim(std::string("render ") + bad.arguments);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find(bad.mentions), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(bad.range), std::string::npos) << r.output;
}

INSTANTIATE_TEST_SUITE_P(
    Table, RenderCliBadArguments,
    ::testing::Values(
        BadArguments{"SizeTooSmall", "--default --size 10x10 --out v.png", "--size = 10x10", "[64, 4096]"},
        BadArguments{"SizeNotWxH", "--default --size wide --out v.png", "--size = wide", "[64, 4096]"},
        BadArguments{"DialBeyondRange", "--default --dials 200,0 --out v.png", "--dials = 200,0",
                     "[-180, 180]"},
        BadArguments{"InsertionBeyondRange", "--default --insertion-mm 5000 --out v.png", "--insertion-mm",
                     "1700"},
        BadArguments{"RotationNotANumber", "--default --rotation-deg nan --out v.png", "--rotation-deg",
                     "720"},
        BadArguments{"NoFrames", "--default --operator expert --contact-sheet s.png --frames 0", "--frames",
                     "64"},
        BadArguments{"NoOutput", "--default", "--out", "--contact-sheet"},
        BadArguments{"NoColon", "--out v.png", "--default", "--case"}),
    [](const ::testing::TestParamInfo<BadArguments>& info) { return std::string(info.param.name); });

TEST(RenderCli, HelpExitsZero)
{
    const auto r = runColonosim("render --help");
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.output.find("--shape-view"), std::string::npos);
}

TEST(RenderCli, WritesViewAndShapePngsOfTheAskedSize)
{
    const std::filesystem::path dir(COLONOSIM_TEST_ARTEFACTS);
    std::filesystem::create_directories(dir);
    const auto view = dir / "cli_view.png";
    const auto shape = dir / "cli_shape.png";
    std::filesystem::remove(view);
    std::filesystem::remove(shape);
    const auto r = runColonosim("render --default --insertion-mm 60 --size 320x200 --out " + view.string() +
                                " --shape-view " + shape.string());
    ASSERT_EQ(r.status, 0) << r.output;
    for (const auto& path : {view, shape}) {
        const QImage image(QString::fromStdString(path.string()));
        ASSERT_FALSE(image.isNull()) << path;
        EXPECT_EQ(image.width(), 320) << path;
        EXPECT_EQ(image.height(), 200) << path;
    }
    // The view is not blank: the lit wall fills part of the image circle.
    const QImage image(QString::fromStdString(view.string()));
    int lit = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            lit += qGray(image.pixel(x, y)) > 60 ? 1 : 0;
        }
    }
    EXPECT_GT(lit, image.width() * image.height() / 10);
}

TEST(RenderCli, AContactSheetTilesFramesAlongARunAndReportsTheMucosaSeen)
{
    const std::filesystem::path dir(COLONOSIM_TEST_ARTEFACTS);
    std::filesystem::create_directories(dir);
    const auto sheet = dir / "cli_contact_sheet.png";
    std::filesystem::remove(sheet);
    const auto r = runColonosim("render --default --operator expert --contact-sheet " + sheet.string() +
                                " --max-time 4 --frames 4 --size 160x120");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("4 frames over 4"), std::string::npos) << r.output;
    // The mucosa seen, overall and per segment, from the renderer's coverage.
    const size_t at = r.output.find("mucosa visualised ");
    ASSERT_NE(at, std::string::npos) << r.output;
    const double seen = std::stod(r.output.substr(at + std::string("mucosa visualised ").size()));
    EXPECT_GT(seen, 0.0) << r.output;
    EXPECT_LT(seen, 20.0) << "4 s in the rectum sees a small part of the colon: " << r.output;
    EXPECT_NE(r.output.find("rectum "), std::string::npos) << r.output;
    // Four tiles side by side, each with the lit wall in it.
    const QImage image(QString::fromStdString(sheet.string()));
    ASSERT_FALSE(image.isNull());
    EXPECT_EQ(image.width(), 4 * 160);
    EXPECT_EQ(image.height(), 120);
    for (int tile = 0; tile < 4; ++tile) {
        int lit = 0;
        for (int y = 0; y < 120; ++y) {
            for (int x = tile * 160; x < (tile + 1) * 160; ++x) {
                lit += qGray(image.pixel(x, y)) > 60 ? 1 : 0;
            }
        }
        EXPECT_GT(lit, 160 * 120 / 20) << "tile " << tile;
    }
}

}  // namespace
