/// \file
/// `colonosim render`: headless images of the endoscope view and the
/// scope-shape view (OSMesa), at a scope state or along a scripted run.
///   render --default|--case FILE [--insertion-mm D] [--rotation-deg R] [--dials U,L]
///          --out view.png [--shape-view shape.png] [--size WxH]
///   render --default|--case FILE --operator expert|novice --contact-sheet sheet.png
///          [--max-time S] [--frames N] [--size WxH]
/// The scope is inserted by the procedure loop (1 kHz) at 5 cm/s to the
/// requested state, which then settles for 0.2 s; the wall is the colon's
/// physics mesh mapped onto the visual mesh.

#include "case_generator/SceneSettings.h"
#include "case_generator/SceneSpec.h"
#include "simcore/geometry/MeshMapping.h"
#include "simcore/geometry/ProceduralColon.h"
#include "simcore/procedure/Operator.h"
#include "simcore/render/CoverageTracker.h"
#include "simcore/render/EndoscopeView.h"
#include "simcore/render/LensSoiling.h"
#include "simcore/render/OffscreenContext.h"
#include "simcore/render/ShapeView.h"
#include "trainer_ui/cli/CaseArgument.h"
#include "trainer_ui/cli/CommandLine.h"
#include "trainer_ui/cli/Commands.h"
#include "trainer_ui/cli/SceneFindings.h"

#include <QFont>
#include <QGuiApplication>
#include <QImage>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <numbers>
#include <sstream>

namespace colonosim::cli {

namespace {
constexpr double kInsertSpeed = 0.05;  ///< m/s while the command inserts the scope
constexpr double kSettleTime = 0.2;    ///< s the scope settles at its state

struct ImageSize {
    int width = 640;
    int height = 480;
};

ImageSize parseSize(const std::optional<std::string>& text)
{
    if (!text) {
        return {};
    }
    int w = 0;
    int h = 0;
    char x = 0;
    std::istringstream in(*text);
    if (!(in >> w >> x >> h) || x != 'x' || !in.eof() || w < 64 || h < 64 || w > 4096 || h > 4096) {
        throw UsageError("--size = " + *text + " is not WIDTHxHEIGHT with each in [64, 4096] pixels");
    }
    return {w, h};
}

std::pair<double, double> parseDials(const std::optional<std::string>& text)
{
    if (!text) {
        return {0.0, 0.0};
    }
    double u = 0.0;
    double l = 0.0;
    char comma = 0;
    std::istringstream in(*text);
    if (!(in >> u >> comma >> l) || comma != ',' || !in.eof() || !(std::abs(u) <= 180.0) ||
        !(std::abs(l) <= 180.0)) {
        throw UsageError("--dials = " + *text + " is not UP,LEFT in degrees, each in [-180, 180] deg");
    }
    return {u * std::numbers::pi / 180.0, l * std::numbers::pi / 180.0};
}

QImage toQImage(const render::RgbaImage& image)
{
    return QImage(image.pixels.data(), image.width, image.height, image.width * 4, QImage::Format_RGBA8888)
        .copy();
}

void save(const QImage& image, const std::string& path)
{
    if (!image.save(QString::fromStdString(path), "PNG")) {
        throw std::runtime_error("cannot write " + path);
    }
}

void label(QImage& image, const std::string& text)
{
    QPainter painter(&image);
    painter.setPen(QColor(235, 235, 235));
    QFont font = painter.font();
    font.setPixelSize(std::max(10, image.height() / 22));
    painter.setFont(font);
    painter.drawText(QRect(8, 4, image.width() - 16, image.height() / 8), Qt::AlignLeft | Qt::AlignTop,
                     QString::fromStdString(text));
}

render::CameraPose poseOf(const scope::TipPose& tip)
{
    return {tip.position, tip.rotation};
}

/// Everything a frame needs: the anatomy, the loop, the wall and the views.
struct Scene {
    geometry::ColonAnatomy anatomy;
    render::WallSurface surface;
    geometry::MeshMapping mapping;
    Eigen::Matrix3Xd visual;
};
}  // namespace

int runRender(std::span<char* const> args)
{
    const CommandLine line(args, {"--default", "--help"},
                           {"--case", "--insertion-mm", "--rotation-deg", "--dials", "--soiling", "--out",
                            "--shape-view", "--size", "--operator", "--contact-sheet", "--max-time",
                            "--frames"});
    if (line.has("--help")) {
        std::cout
            << "usage: colonosim render --default|--case FILE [--insertion-mm D] [--rotation-deg R]\n"
               "                        [--dials U,L] --out view.png [--shape-view shape.png] [--size WxH]\n"
               "       colonosim render --default|--case FILE --operator expert|novice\n"
               "                        --contact-sheet sheet.png [--max-time S] [--frames N] [--size WxH]\n"
               "Headless images (OSMesa) of the endoscope view and the scope-shape view.\n"
               "  --insertion-mm D   inserted length, 0-1700 mm (default 150)\n"
               "  --rotation-deg R   shaft rotation at the handle, -720-720 deg (default 0)\n"
               "  --dials U,L        tip dials up and left, each -180-180 deg (default 0,0)\n"
               "  --size WxH         image size, each 64-4096 pixels (default 640x480; sheet tiles 320x240)\n"
               "  --max-time S       contact sheet: simulated seconds of the run, 1-3600 (default 60)\n"
               "  --frames N         contact sheet: frames along the run, 1-64 (default 12)\n";
        return 0;
    }
    const std::optional<std::string> caseFile = line.value("--case");
    if (caseFile.has_value() == line.has("--default")) {
        throw UsageError("choose the colon: --default or --case FILE (one of them)");
    }
    const std::optional<std::string> out = line.value("--out");
    const std::optional<std::string> sheet = line.value("--contact-sheet");
    const std::optional<std::string> operatorName = line.value("--operator");
    if (out.has_value() == sheet.has_value()) {
        throw UsageError("choose the output: --out view.png or --operator NAME --contact-sheet sheet.png");
    }
    if (sheet.has_value() != operatorName.has_value()) {
        throw UsageError("--contact-sheet and --operator go together (see --help)");
    }
    const double insertion = line.number("--insertion-mm", 150.0, 0.0, 1700.0, "mm") / 1000.0;
    const double rotation =
        line.number("--rotation-deg", 0.0, -720.0, 720.0, "deg") * std::numbers::pi / 180.0;
    const auto [dialUp, dialLeft] = parseDials(line.value("--dials"));
    const double soiling = line.number("--soiling", 0.0, 0.0, 1.0, "");
    const double maxTime = line.number("--max-time", 60.0, 1.0, 3600.0, "s");
    const int frames = static_cast<int>(line.number("--frames", 12.0, 1.0, 64.0, ""));
    const ImageSize size = line.value("--size") ? parseSize(line.value("--size"))
                                                : (sheet ? ImageSize{320, 240} : ImageSize{640, 480});
    std::unique_ptr<procedure::Operator> driver =
        operatorName ? procedure::makeOperator(*operatorName) : nullptr;

    procedure::ProcedureSettings settings;
    geometry::AnatomyParameters anatomyParameters;
    render::WallFindings findings;
    if (caseFile) {
        const cases::Case theCase = readCaseArgument(*caseFile);
        const cases::SceneSpec scene = cases::toScene(theCase);
        anatomyParameters = scene.anatomy;
        settings = cases::procedureSettings(scene);
        findings = findingsOf(scene);
    }

    // QPainter's text needs a QGuiApplication; the offscreen platform needs no display.
    setenv("QT_QPA_PLATFORM", "offscreen", 0);
    int qtArgc = 1;
    char qtName[] = "colonosim";
    char* qtArgv[] = {qtName, nullptr};
    QGuiApplication application(qtArgc, qtArgv);

    Scene scene;
    scene.anatomy = geometry::buildProceduralColon(anatomyParameters);
    scene.surface = render::buildWallSurface(scene.anatomy.visualMesh, scene.anatomy.centreline, findings);
    scene.mapping = geometry::MeshMapping(scene.anatomy.physicsMesh, scene.surface.rest.vertices);
    procedure::ProcedureLoop loop(scene.anatomy, settings);

    render::OffscreenContext context(size.width, size.height);
    render::RenderParameters parameters;
    render::EndoscopeView view(context.gl(), scene.surface, parameters);
    const auto drawView = [&](double lensSoiling) {
        scene.mapping.apply(loop.colon().body.positions(), scene.visual);
        view.setWallPositions(scene.visual);
        view.setBleedingMarks(loop.bleedingMarks());
        view.render(poseOf(loop.outputs().tip), {lensSoiling, 0.0, loop.lastFrame().lensWallDistance},
                    size.width, size.height);
        return toQImage(context.readBack());
    };

    if (out) {
        procedure::InputSample input;
        input.rotation = rotation;
        input.dialUpDown = dialUp;
        input.dialLeftRight = dialLeft;
        const double dt = loop.trace().loopStep;
        const auto insertSteps = static_cast<long>(std::ceil(insertion / kInsertSpeed / dt));
        const auto settleSteps = static_cast<long>(kSettleTime / dt);
        for (long s = 1; s <= insertSteps + settleSteps; ++s) {
            input.insertion = std::min(insertion, static_cast<double>(s) * kInsertSpeed * dt);
            loop.step(input);
        }
        QImage image = drawView(soiling);
        save(image, *out);
        std::cout << "endoscope view: " << *out << " (" << size.width << "x" << size.height << "), insertion "
                  << insertion * 1000.0 << " mm, red-out " << view.redOut() << '\n';
        // The command pushes straight in without steering; on a tortuous colon the
        // tip can end up through the wall, where the view shows nothing of the lumen.
        const double depth = loop.lumen().contacts().back().depth;
        if (depth > settings.scope.outerDiameter) {
            std::cerr << "render: the unsteered push to " << insertion * 1000.0 << " mm has carried the tip "
                      << std::lround(depth * 1000.0) << " mm into the wall (more than the scope's "
                      << std::lround(settings.scope.outerDiameter * 1000.0)
                      << " mm diameter), so the view shows no lumen; steer with --dials and --rotation-deg, "
                         "or follow a scripted operator with --operator expert --contact-sheet\n";
        }
        if (const auto shapePath = line.value("--shape-view")) {
            render::ShapeView shape(context.gl());
            std::vector<Eigen::Vector3d> nodes(loop.scope().nodePositions().begin(),
                                               loop.scope().nodePositions().end());
            const procedure::LoopKind kind = loop.loops().current();
            std::optional<geometry::Segment> loopSegment;
            if (kind != procedure::LoopKind::None) {
                loopSegment = loop.loops().signals().segment;
            }
            shape.render(scene.anatomy.centreline, nodes, loopSegment, settings.scope.outerDiameter,
                         size.width, size.height);
            QImage shapeImage = toQImage(context.readBack());
            label(shapeImage, "anterior | lateral (left)    loop: " + std::string(procedure::loopName(kind)));
            save(shapeImage, *shapePath);
            std::cout << "scope-shape view: " << *shapePath << ", loop " << procedure::loopName(kind) << '\n';
        }
        return 0;
    }

    // Contact sheet: frames evenly spread over the run, coverage at its own rate.
    std::vector<geometry::Segment> triangleSegment;
    for (const auto& t : scene.anatomy.physicsMesh.triangles) {
        triangleSegment.push_back(scene.anatomy.physicsNodes[static_cast<size_t>(t[0])].segment);
    }
    render::CoverageTracker coverage(context.gl(), scene.anatomy.physicsMesh, triangleSegment, parameters);
    std::vector<std::vector<int>> lesionTriangles;
    for (size_t l = 0; l < findings.lesions.size(); ++l) {
        lesionTriangles.push_back(render::trianglesNear(scene.anatomy.physicsMesh,
                                                        scene.surface.lesionTops[l],
                                                        findings.lesions[l].diameter / 2.0 + 0.01));
    }
    coverage.setLesionTriangles(lesionTriangles);
    std::vector<bool> lesionSeen(findings.lesions.size(), false);
    const int columns = std::min(frames, 4);
    const int rows = (frames + columns - 1) / columns;
    QImage contact(columns * size.width, rows * size.height, QImage::Format_RGBA8888);
    contact.fill(Qt::black);
    const double frameInterval = maxTime / frames;
    int taken = 0;
    render::LensSoiling lens(parameters);
    const double dt = loop.trace().loopStep;
    const auto steps = static_cast<long>(maxTime / dt);
    for (long s = 0; s < steps && !driver->finished(); ++s) {
        loop.step(driver->next(loop));
        const procedure::ProcedureFrame& now = loop.lastFrame();
        lens.update(dt, now.lensWallDistance, (now.input.buttons & procedure::kWater) != 0);
        if (coverage.update(loop.time(), loop.colon().body.positions(), poseOf(loop.outputs().tip))) {
            for (size_t l = 0; l < lesionSeen.size(); ++l) {
                lesionSeen[l] = lesionSeen[l] || coverage.lesionsInView()[l];
            }
        }
        if (loop.time() + 1e-9 >= (taken + 1) * frameInterval && taken < frames) {
            QImage frame = drawView(lens.amount());
            std::ostringstream text;
            text.precision(3);
            text << "t " << loop.time() << " s  insertion " << loop.lastFrame().input.insertion * 100.0
                 << " cm  seen " << coverage.fractionSeen() * 100.0 << "%";
            label(frame, text.str());
            QPainter painter(&contact);
            painter.drawImage((taken % columns) * size.width, (taken / columns) * size.height, frame);
            ++taken;
        }
    }
    save(contact, *sheet);
    std::cout << "contact sheet: " << *sheet << ", " << taken << " frames over " << loop.time()
              << " s; mucosa visualised " << coverage.fractionSeen() * 100.0 << "%";
    for (int s = 0; s < geometry::kNumSegments; ++s) {
        const auto segment = static_cast<geometry::Segment>(s);
        std::cout << (s == 0 ? " (" : ", ") << geometry::segmentName(segment) << ' '
                  << coverage.fractionSeen(segment) * 100.0 << '%';
    }
    std::cout << ")\nlesions in view at least once: "
              << std::count(lesionSeen.begin(), lesionSeen.end(), true) << " of " << lesionSeen.size()
              << '\n';
    return 0;
}

}  // namespace colonosim::cli
