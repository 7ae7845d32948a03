#pragma once
/// \file
/// The endoscope view: the mapped wall seen through the tip's fisheye lens
/// (Shaders.h), lit by the tip's light, then the lens pass.
///
/// Pass 0, once: the procedural mucosa (vessel network, colour variation,
///   stool pattern, relief) is baked into a tiling, mipmapped texture, so a
///   frame costs texture reads instead of noise evaluations per pixel.
/// Pass 1, into an offscreen colour + depth target: the wall with
///   irradiance E = I (1 cm / d)^2 cos(alpha)^k  (light at the lens, inverse
///   square, light-guide cone of exponent k at angle alpha off axis),
///   Lambert diffuse on a procedural albedo (vessel network, noise, lesion
///   colour, stool) with the normal perturbed by a procedural height field
///   (bump mapping by screen-space derivatives), and a sharp Blinn-Phong
///   lobe for the wet mucosa (light and eye coincide, so H = L).
/// Pass 2, to the host's framebuffer: lens soiling (a screen-space mask of
///   droplets whose extent grows with the soiling amount; under it the image
///   is blurred and veiled), red-out, and the black surround of the image
///   circle. The droplet mask is drawn into a texture only when the soiling
///   crosses a step of 1/64, its seed or the size changes; the blur (a disc
///   of 9/480 of the image height, the same share at any scale) reads the
///   scene reduced by a power of two near 0.45 of its radius.
/// Culling: the triangles are drawn in chunks (TubeLevelsOfDetail.h; 16
/// rings of a tube grid, else 2048 consecutive triangles); a chunk is
/// skipped when its bounding sphere lies wholly beyond the far distance or
/// wholly outside the cone of the clipped field (1.05 x half the field of
/// view, as the clip distance).
/// Levels of detail: a chunk of a tube grid is drawn at the coarsest level
/// whose geometric error, seen from the sphere's nearest point, stays within
/// levelOfDetailError pixels (field of view / height radians each).
/// Automatic light control: with the nearest wall within autoLightCone of
/// the view axis at d below
/// autoLightDistance D_a, the light is scaled by max((d / D_a)^2, 0.02), as a
/// video processor's automatic brightness keeps a near wall from glaring.
/// Bleeding marks (setBleedingMarks): each mark darkens the albedo towards
///   haemorrhage red within its radius on the chart, the rim broken by the
///   baked relief noise and softened over the outer 35%. The marks are a
///   uniform array in chart coordinates, so they stay at their place of the
///   tissue; a per-vertex flag (set when the marks change) limits the
///   per-fragment loop to triangles within reach of a mark.
/// Residual fluid (WallSurface::fluidDepth, ResidualFluid.h): where the
///   wall lies a depth z below its pool's level, the view ray from the lens
///   (the light's place too) runs x = min(z / |ray.up|, |ray|) through the
///   liquid, as the surface is a horizontal plane. The wall's light comes
///   back attenuated by exp(-2 mu_c x) per colour channel c (in and out;
///   mu from fluidAttenuation, more in blue, so the mucosa seen through is
///   yellow-brown and fades with depth and grazing views), the liquid adds
///   its own back-scatter, (1 - exp(-2 mu x)) times a yellow-brown albedo
///   and (0.35 + 0.65 cos) of the light's incidence on the surface, and the
///   flat surface a mirror-like highlight, specular * 4 * (up.L)^400 (light
///   and eye coincide): a sharp spot where the surface faces the lens. The
///   wall's own wet highlight is not drawn under the liquid. With the lens
///   itself below the level the submerged wall is seen through the whole ray,
///   the liquid scatters back as lit one round-trip attenuation length
///   1 / (2 mu) ahead (a yellow-brown murk), and the wall above the level is
///   drawn dry (a lens in the pool is a moment's event: the endoscopist
///   suctions or lifts the tip).
/// Red-out: amount = clamp((D_red - d) / (D_red - D_contact), 0, 1), d the
/// distance from the lens to the nearest wall vertex ahead of it, or the
/// simulation's lens-wall distance when nearer (LensState::wallDistance).

#include "simcore/render/FisheyeLens.h"
#include "simcore/render/GlFunctions.h"
#include "simcore/render/RenderParameters.h"
#include "simcore/render/ShaderProgram.h"
#include "simcore/render/TubeLevelsOfDetail.h"
#include "simcore/render/WallSurface.h"

#include <Eigen/Core>

#include <array>
#include <limits>
#include <memory>
#include <vector>

namespace colonosim::render {

/// What the lens itself adds to the picture.
struct LensState {
    double soiling = 0.0;      ///< 0 clean .. 1 covered (lens wash brings it to 0)
    double soilingSeed = 0.0;  ///< moves the droplet pattern
    /// m from the lens to the wall as the simulation has it
    /// (ProcedureFrame::lensWallDistance: 0 at the wall or through it), or
    /// infinity when unknown. Red-out takes the nearer of this and the
    /// renderer's own distance to the wall ahead: a lens pressed through the
    /// wall's surface has no wall ahead of it, and a real scope there shows
    /// red-out, not black.
    double wallDistance = std::numeric_limits<double>::infinity();
};

class EndoscopeView {
public:
    /// Needs a current context whose functions are `gl`. Throws RenderError
    /// (GL) or ParameterError (parameters).
    EndoscopeView(const GlFunctions& gl, const WallSurface& surface, const RenderParameters& parameters);
    ~EndoscopeView();
    EndoscopeView(const EndoscopeView&) = delete;
    EndoscopeView& operator=(const EndoscopeView&) = delete;

    /// The wall's current visual vertex positions (one column per vertex of
    /// surface.rest, e.g. MeshMapping::apply of the physics positions).
    /// Computes the smooth normals and uploads both.
    void setWallPositions(const Eigen::Matrix3Xd& positions);

    /// The contact bleeding marks to draw (at most kMaxBleedingMarks; more
    /// are ignored). Cheap when unchanged; otherwise O(vertices x marks).
    void setBleedingMarks(const std::vector<BleedingMark>& marks);

    /// Draws the view into `framebuffer` (0: the context's default) of
    /// width x height pixels.
    void render(const CameraPose& pose, const LensState& lens, int width, int height, GLuint framebuffer = 0);

    /// Triangles drawn by the last render (after culling and levels of detail).
    [[nodiscard]] int drawnTriangles() const { return m_drawnTriangles; }
    /// Red-out amount (0..1) of the last render.
    [[nodiscard]] double redOut() const { return m_redOut; }
    /// Distance from `point` to the nearest wall vertex within `coneAngle`
    /// (rad) of `forward` (pi/2: the half-space ahead), m (infinity when none).
    [[nodiscard]] double wallDistanceAhead(const Eigen::Vector3d& point, const Eigen::Vector3d& forward,
                                           double coneAngle = 1.5707963267948966) const;
    /// wallDistanceAhead() within each of the cones, in one pass over the wall.
    [[nodiscard]] std::array<double, 2> wallDistancesAhead(const Eigen::Vector3d& point,
                                                           const Eigen::Vector3d& forward,
                                                           const std::array<double, 2>& coneAngles) const;
    [[nodiscard]] FisheyeLens lens(int width, int height) const
    {
        return {m_parameters.fieldOfView, width, height};
    }

private:
    void resizeTarget(int width, int height);
    /// Draws the soiling's droplet mask (Shaders.h, kLensMaskFragment) when
    /// the soiling, its seed or the size changed.
    void updateLensMask(const LensState& lens, int width, int height);
    /// Draws the scene reduced for the soiling's blur (Shaders.h,
    /// kLensReduceFragment) of `blurRadius` pixels.
    void reduceForBlur(double blurRadius, int width, int height);
    void bakeMucosa();
    /// Draws the screen-filling triangle (Shaders.h, kScreenVertex) with the
    /// program in use.
    void drawScreenTriangle() const;

    const GlFunctions& m_gl;
    RenderParameters m_parameters;
    std::unique_ptr<ShaderProgram> m_wall;
    std::unique_ptr<ShaderProgram> m_lens;
    std::unique_ptr<ShaderProgram> m_cleanLens;   ///< the lens pass without soiling and red-out
    std::unique_ptr<ShaderProgram> m_lensMask;    ///< draws the soiling's droplet mask
    std::unique_ptr<ShaderProgram> m_lensReduce;  ///< reduces the scene for the soiling's blur
    GLuint m_vao = 0;
    GLuint m_screenVao = 0;
    GLuint m_dynamicBuffer = 0;
    GLuint m_staticBuffer = 0;
    GLuint m_indexBuffer = 0;
    GLuint m_bleedingBuffer = 0;  ///< 1 float per vertex: 1 within reach of a mark
    GLuint m_mucosa = 0;          ///< the baked, tiling mucosa texture (Shaders.h, kMucosaBake)
    GLuint m_targetFramebuffer = 0;
    GLuint m_targetColour = 0;
    GLuint m_targetDepth = 0;
    int m_targetWidth = 0;
    int m_targetHeight = 0;
    ColourTarget m_mask;          ///< R8, the soiling's droplet mask at the target's size
    double m_maskSoiling = -1.0;  ///< the soiling it was drawn for (in steps of 1/64)
    double m_maskSeed = 0.0;
    ColourTarget m_blur;  ///< the scene reduced for the soiling's blur
    /// The soiling's blur radius as a fraction of the image height (9 pixels
    /// of 480).
    static constexpr double kSoilingBlurRadius = 9.0 / 480.0;
    TubeLevelsOfDetail m_levels;         ///< the chunks and their levels of detail
    std::vector<double> m_chunkNearest;  ///< per chunk, per frame (TubeLevelsOfDetail::drawList)
    std::vector<std::array<int, 3>> m_triangles;
    Eigen::Matrix3Xd m_positions;
    Eigen::Matrix3Xd m_normals;
    std::vector<float> m_upload;
    std::vector<float> m_chart;           ///< the surface's chart, 3 per vertex (m)
    Eigen::Matrix3Xd m_restVertices;      ///< the surface's rest vertices (m), to place marks on the chart
    std::vector<BleedingMark> m_marks;    ///< as last set
    std::vector<WallPlace> m_markPlaces;  ///< each mark's place on the chart
    std::vector<float> m_markUniforms;    ///< 4 per mark: s (mm), angle (rad), radius (mm), opacity
    std::vector<float> m_bleedingNear;    ///< per vertex
    /// Per vertex, its chart's distance from the centreline (m) and angle
    /// round it (rad): the marks' reach is measured with them.
    std::vector<double> m_chartRadius;
    std::vector<double> m_chartAngle;
    std::vector<int> m_byArc;         ///< the vertices in the order of their chart's arc length
    std::vector<double> m_arcSorted;  ///< their arc lengths, m, in that order
    Eigen::Vector3d m_up;             ///< against gravity: the fluid surface's normal
    double m_redOut = 0.0;
    int m_drawnTriangles = 0;
};

}  // namespace colonosim::render
