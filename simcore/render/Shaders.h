#pragma once
/// \file
/// GLSL 330 core sources of every pass, shared by all hosts.
///
/// Projection (all 3D passes): an equidistant ("f-theta") fisheye, evaluated
/// per vertex. A camera-frame point c at angle theta = acos(c_z / |c|) from
/// the view axis lands at image radius theta / halfFieldOfView (1 = the edge
/// of the image circle, which fills the image height), in the direction of
/// (c_x, c_y). This is the barrel distortion of an endoscope's wide-angle
/// lens, and unlike a perspective projection it covers 140-170 degrees in a
/// single pass. Depth is the linear distance |c| between near and far. The
/// projection is evaluated at the vertices only, so a triangle's edges stay
/// straight in the image; with the visual mesh's 2-3 mm edges the error is a
/// fraction of a pixel beyond a few centimetres. Points beyond the image
/// circle (5% margin) are clipped (gl_ClipDistance): nothing is shaded
/// where the image is black, and nothing can wrap around behind the lens.
/// A triangle whose vertices all lie outside while its middle is in view
/// would be lost; with 2-3 mm edges that needs the lens within about
/// 1.5 mm of it, where the view is red-out anyway.

namespace colonosim::render::shaders {

/// Shared vertex-stage projection.
inline constexpr const char* kFisheye = R"(
uniform mat3 uWorldToCamera;
uniform vec3 uCameraPosition;
uniform float uHalfFieldOfView;
uniform float uAspect;
uniform vec2 uDepthRange;
vec4 fisheye(vec3 world, out vec3 cameraPoint)
{
    vec3 c = uWorldToCamera * (world - uCameraPosition);
    cameraPoint = c;
    float d = max(length(c), 1e-9);
    float theta = acos(clamp(c.z / d, -1.0, 1.0));
    float rxy = length(c.xy);
    vec2 direction = rxy > 1e-12 ? c.xy / rxy : vec2(0.0);
    vec2 image = direction * theta / uHalfFieldOfView;
    image.x /= uAspect;
    gl_ClipDistance[0] = uHalfFieldOfView * 1.05 - theta;
    float depth = (d - uDepthRange.x) / (uDepthRange.y - uDepthRange.x);
    return vec4(image, depth * 2.0 - 1.0, 1.0);
}
)";

/// The wall: mapped visual mesh with its static surface attributes.
inline constexpr const char* kWallVertex = R"(
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aSurface;   // chart: s, r cos(theta), r sin(theta) (m)
layout(location = 3) in vec4 aFinding;   // lesion weight, tissue code, stool, diverticulum
layout(location = 4) in float aBleedingNear;  // 1 within reach of a bleeding mark
layout(location = 5) in float aFluidDepth;    // m below the residual fluid's surface
out vec3 vWorld;
out vec3 vNormal;
out vec3 vSurface;
out vec4 vFinding;
out float vBleedingNear;
out float vFluidDepth;
void main()
{
    vec3 c;
    gl_Position = fisheye(aPosition, c);
    vWorld = aPosition;
    vNormal = aNormal;
    vSurface = aSurface;
    vFinding = aFinding;
    vBleedingNear = aBleedingNear;
    vFluidDepth = aFluidDepth;
}
)";

/// Value noise and fractal sums on the wall's (arc length, angle) chart.
inline constexpr const char* kNoise = R"(
// Integer hash of a lattice point (exact at any coordinate size).
float hash(vec3 p)
{
    uvec3 q = uvec3(ivec3(floor(p)) + 65536);
    uint h = (q.x * 1597334673u) ^ (q.y * 3812015801u) ^ (q.z * 2798796415u);
    h = (h ^ (h >> 16u)) * 2246822519u;
    h ^= h >> 13u;
    return float(h) * (1.0 / 4294967295.0);
}
float noise(vec3 p)
{
    vec3 i = floor(p);
    vec3 f = fract(p);
    vec3 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(mix(hash(i), hash(i + vec3(1, 0, 0)), u.x),
                   mix(hash(i + vec3(0, 1, 0)), hash(i + vec3(1, 1, 0)), u.x), u.y),
               mix(mix(hash(i + vec3(0, 0, 1)), hash(i + vec3(1, 0, 1)), u.x),
                   mix(hash(i + vec3(0, 1, 1)), hash(i + vec3(1, 1, 1)), u.x), u.y), u.z);
}
float fbm(vec3 p)
{
    float sum = 0.0;
    float amplitude = 0.5;
    for (int k = 0; k < 4; ++k) {
        sum += amplitude * noise(p);
        p = p * 2.03 + vec3(17.1, 3.7, 9.2);
        amplitude *= 0.5;
    }
    return sum;
}
)";

/// Periodic 2D value noise for the baked mucosa texture: lattice indices
/// wrap with `period` (doubling with each octave), so the texture tiles.
inline constexpr const char* kPeriodicNoise = R"(
float phash(vec2 i, vec2 period)
{
    uvec2 q = uvec2(ivec2(mod(i, period)));
    uint h = (q.x * 1597334673u) ^ (q.y * 3812015801u);
    h = (h ^ (h >> 16u)) * 2246822519u;
    h ^= h >> 13u;
    return float(h) * (1.0 / 4294967295.0);
}
float pnoise(vec2 p, vec2 period)
{
    vec2 i = floor(p);
    vec2 f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(phash(i, period), phash(i + vec2(1.0, 0.0), period), u.x),
               mix(phash(i + vec2(0.0, 1.0), period), phash(i + vec2(1.0, 1.0), period), u.x), u.y);
}
float pfbm(vec2 p, vec2 period)
{
    float sum = 0.0;
    float amplitude = 0.5;
    for (int k = 0; k < 4; ++k) {
        sum += amplitude * pnoise(p, period);
        p *= 2.0;
        period *= 2.0;
        amplitude *= 0.5;
    }
    return sum;
}
)";

/// Bakes one tile of the mucosa (kTileMillimetres of arc length by one
/// turn, written as kTileMillimetres of reference circumference) into RGBA:
/// R vessel network, G albedo variation, B stool pattern, A relief (0..1).
/// Every lattice scale is a whole number of cells per tile, so it repeats.
inline constexpr const char* kMucosaBake = R"(
in vec2 vUv;
out vec4 fragColour;
const float kTile = 160.0;  // mm
float vesselLines(vec2 p, vec2 period)
{
    vec2 warp = vec2(pfbm(p * 0.5, period * 0.5), pfbm(p * 0.5 + vec2(5.0, 1.0), period * 0.5));
    vec2 q = p + 1.6 * warp;
    float v = abs(pnoise(q, period) - 0.5);
    float v2 = abs(pnoise(q * 2.0 + vec2(3.0), period * 2.0) - 0.5) * 2.0;
    float large = 1.0 - smoothstep(0.02 - fwidth(v), 0.02 + fwidth(v), v);
    float small = 1.0 - smoothstep(0.022 - fwidth(v2), 0.022 + fwidth(v2), v2);
    return max(large, 0.55 * small);
}
void main()
{
    vec2 mm = vUv * kTile;
    float vessel = vesselLines(mm * 0.15, vec2(24.0));
    float variation = pfbm(mm * 0.25, vec2(40.0));
    float stool = pfbm(mm * 0.075, vec2(12.0));
    float relief = 0.9 * pfbm(mm * 0.9, vec2(144.0)) + 0.1 * pnoise(mm * 2.0, vec2(320.0));
    fragColour = vec4(vessel, variation, stool, relief);
}
)";

inline constexpr const char* kWallFragment = R"(
in vec3 vWorld;
in vec3 vNormal;
in vec3 vSurface;
in vec4 vFinding;
in float vBleedingNear;
in float vFluidDepth;
out vec4 fragColour;
uniform sampler2D uMucosa;
uniform int uBleedingCount;
uniform vec4 uBleeding[64];         // kMaxBleedingMarks: s (mm), angle (rad), radius (mm), opacity
uniform vec3 uLightPosition;
uniform float uLightIntensity;      // irradiance scale at 1 cm
uniform float uSpotExponent;
uniform vec3 uViewAxis;
uniform float uSpecular;
uniform float uBumpDepth;           // m
uniform float uFluidAttenuation;    // 1/m, green; red and blue scaled by kFluidSpectrum
uniform vec3 uUp;                   // against gravity: the fluid surface's normal
const float kTile = 160.0;          // mm, as in the bake
const vec3 kFluidSpectrum = vec3(0.6, 1.0, 1.8);  // bile absorbs blue most: yellow-brown
const vec3 kFluidAlbedo = vec3(0.60, 0.42, 0.13);  // back-scatter of turbid residual fluid
// The baked tile at chart (s, angle), scaled by `zoom`. atan's branch cut
// at +-pi makes the angle jump by a whole turn between neighbouring pixels;
// there the other branch, fract(turn), is continuous and is used instead
// (Tarini 2012), so the implicit mip selection sees no seam. Away from the
// cut both branches are equal up to rounding, so the first is kept unless
// its screen derivative shows the jump (a quarter turn per pixel or more).
vec4 mucosa(vec3 chart, float zoom)
{
    float turn = atan(chart.z, chart.y) / 6.2831853;
    float jump = abs(dFdx(turn)) + abs(dFdy(turn));
    vec2 uv = vec2(chart.x / kTile, jump < 0.25 ? turn : fract(turn)) * zoom;
    return texture(uMucosa, uv);
}
void main()
{
    vec3 chart = vSurface * 1000.0;  // mm
    vec4 m = mucosa(chart, 1.0);
    float lesion = vFinding.x;
    // Tissue: 0 adenoma, 1 serrated, 2 cancer (their own surface, with a pit
    // pattern), 3 lipoma (under intact mucosa: the normal surface).
    int tissue = int(vFinding.y + 0.5);
    bool lipoma = tissue == 3;
    float pits = lipoma ? 0.0 : lesion;
    vec4 fineDetail = pits > 0.0 ? mucosa(chart, 5.0) : vec4(0.5);
    vec3 toLight = uLightPosition - vWorld;
    float distance = max(length(toLight), 1e-4);
    vec3 L = toLight / distance;
    // A vertex with no area around it has no normal: face the light.
    vec3 N = dot(vNormal, vNormal) > 1e-12 ? normalize(vNormal) : L;
    if (dot(N, L) < 0.0) {
        N = -N;
    }
    vec3 smoothNormal = N;
    // Normal perturbation from the baked relief (bump mapping by screen derivatives).
    float height = uBumpDepth * (m.a + pits * 2.0 * fineDetail.a);
    vec3 dpdx = dFdx(vWorld);
    vec3 dpdy = dFdy(vWorld);
    float dhdx = dFdx(height);
    float dhdy = dFdy(height);
    vec3 r1 = cross(dpdy, N);
    vec3 r2 = cross(N, dpdx);
    float det = dot(dpdx, r1);
    if (abs(det) > 1e-20) {
        vec3 gradient = sign(det) * (dhdx * r1 + dhdy * r2);
        vec3 bumped = abs(det) * N - gradient;
        // Steep relief (a lesion's edge seen from afar) must not turn the
        // normal past the surface: keep the smooth one there.
        N = dot(bumped, N) > 0.2 * length(bumped) ? normalize(bumped) : N;
    }

    // Mucosa: pink; a lipoma's yellow fat shows through it.
    vec3 albedo = vec3(0.96, 0.46, 0.36) * (0.85 + 0.3 * m.g);
    if (lipoma) {
        albedo = mix(albedo, vec3(0.95, 0.74, 0.34) * (0.9 + 0.2 * m.g), 0.7 * lesion);
    }
    // The submucosal vessel network, hidden by lesions with their own surface.
    albedo = mix(albedo, vec3(0.60, 0.08, 0.10), 0.55 * m.r * (1.0 - pits));

    // Lesions: 0 adenoma (redder, pit pattern), 1 serrated (pale, mucus cap), 2 cancer.
    vec3 lesionColour = tissue == 0 ? vec3(0.86, 0.36, 0.32) * (0.7 + 0.6 * fineDetail.g)
                        : tissue == 1 ? vec3(0.90, 0.74, 0.58) * (0.85 + 0.3 * fineDetail.g)
                                      : vec3(0.55, 0.14, 0.16) * (0.5 + 1.0 * fineDetail.b);
    albedo = mix(albedo, lesionColour, pits);
    // Diverticulum: a dark opening. The light guides sit beside the lens, so
    // the neck shades the sac behind it, which sends little light back: the
    // mouth darkens to 8% over its inner three quarters and shades off to the rim.
    float sac = smoothstep(0.0, 0.25, vFinding.w);
    albedo *= 1.0 - 0.92 * sac;
    // Residual stool: brown-yellow patches covering the given fraction.
    float stoolMask = smoothstep(1.0 - vFinding.z, 1.0 - vFinding.z + 0.08, m.b) * step(0.001, vFinding.z);
    albedo = mix(albedo, vec3(0.58, 0.36, 0.12), stoolMask);
    // Contact bleeding marks: submucosal haemorrhage, dark red under the
    // epithelium, the rim broken by the relief noise and soft over its outer part.
    if (vBleedingNear > 0.0) {
        float r = length(chart.yz);
        float angle = atan(chart.z, chart.y);
        float blood = 0.0;
        for (int k = 0; k < uBleedingCount; ++k) {
            vec4 mark = uBleeding[k];
            float turn = angle - mark.y;
            turn -= 6.2831853 * floor(turn / 6.2831853 + 0.5);
            float d = length(vec2(chart.x - mark.x, r * turn));
            float rim = mark.z * (0.75 + 0.5 * m.a);
            blood = max(blood, mark.w * (1.0 - smoothstep(0.65 * rim, rim, d)));
        }
        vec3 haemorrhage = vec3(0.42, 0.03, 0.04) * (0.8 + 0.4 * m.g);
        albedo = mix(albedo, haemorrhage, blood);
    }

    // Light at the tip: inverse-square fall-off and the light guide's cone.
    float spot = pow(max(dot(-L, uViewAxis), 0.0), uSpotExponent);
    float irradiance = uLightIntensity * 1e-4 / (distance * distance) * spot;
    float diffuse = max(dot(N, L), 0.0);
    // Wet mucosa: a sharp specular lobe (light and eye coincide, so H = L),
    // stronger where mucus pools.
    float wet = uSpecular * (0.5 + m.g) * (1.0 - 0.7 * stoolMask) * (1.0 - sac);
    // The mucus film smooths the relief for the highlight (half the bump).
    vec3 filmNormal = normalize(smoothNormal + N);
    float specular = wet * pow(max(dot(filmNormal, L), 0.0), 90.0);
    vec3 colour = irradiance * (albedo * diffuse + vec3(specular));
    // Residual fluid (EndoscopeView.h): the wall seen through the liquid,
    // the liquid's back-scatter and its level surface's mirror highlight.
    // Compiled only for a wall with fluid: the software rasteriser pays for
    // a branch's body even where no fragment takes it.
#ifdef RESIDUAL_FLUID
    if (vFluidDepth > 0.0) {
        vec3 ray = vWorld - uLightPosition;
        float rayLength = max(length(ray), 1e-6);
        ray /= rayLength;
        float rise = dot(ray, uUp);
        bool lensUnder = vFluidDepth + rayLength * rise > 0.0;
        float path = lensUnder ? rayLength : min(vFluidDepth / max(abs(rise), 1e-3), rayLength);
        vec3 transmission = exp(-2.0 * uFluidAttenuation * path * kFluidSpectrum);
        // Where the liquid scatters back: at its surface, or, with the lens
        // in it, one round-trip attenuation length ahead.
        vec3 surfacePoint = lensUnder ? uLightPosition + ray * min(0.5 / uFluidAttenuation, rayLength)
                                      : vWorld - ray * path;
        vec3 toLens = uLightPosition - surfacePoint;
        float d = max(length(toLens), 1e-4);
        float facing = lensUnder ? 1.0 : max(dot(uUp, toLens / d), 0.0);
        float e = uLightIntensity * 1e-4 / (d * d) * pow(max(dot(-toLens / d, uViewAxis), 0.0), uSpotExponent);
        float scatter = (1.0 - exp(-2.0 * uFluidAttenuation * path)) * (0.35 + 0.65 * facing);
        float mirror = lensUnder ? 0.0 : uSpecular * 4.0 * pow(facing, 400.0);
        colour = irradiance * albedo * diffuse * transmission + e * (kFluidAlbedo * scatter + vec3(mirror));
    }
#endif
    // Film response: soft shoulder instead of clipping.
    colour = vec3(1.0) - exp(-colour * 1.6);
    fragColour = vec4(colour, 1.0);
}
)";

/// Full-screen pass: lens soiling, red-out, image circle. Compiled a second
/// time with LENS_CLEAN defined (image circle only) for frames that need
/// neither effect: the software rasteriser would otherwise pay for them.
inline constexpr const char* kScreenVertex = R"(
out vec2 vUv;
void main()
{
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    vUv = corner;
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";

/// The soiling's droplet mask (0 clear .. 1 under a drop or smear), drawn
/// into a one-channel texture of the view's size whenever the soiling amount
/// (in steps of 1/64) or its seed changes, not every frame: droplets and
/// smears on the lens, on a jittered grid at two scales, a cell holding a
/// round drop when its random number is below the soiling amount; drops grow
/// with it. A thin film veils the rest in proportion.
inline constexpr const char* kLensMaskFragment = R"(
in vec2 vUv;
out vec4 fragColour;
uniform float uAspect;
uniform float uSoiling;   // 0 clean .. 1 fully soiled
uniform float uSeed;
void main()
{
    vec2 p = vec2((vUv.x * 2.0 - 1.0) * uAspect, vUv.y * 2.0 - 1.0);
    float mask = 0.0;
    for (int level = 0; level < 2; ++level) {
        float scale = level == 0 ? 4.0 : 9.0;
        vec2 q = p * scale;
        vec2 cell = floor(q);
        for (int i = -1; i <= 1; ++i) {
            for (int j = -1; j <= 1; ++j) {
                vec2 c = cell + vec2(float(i), float(j));
                float seed = uSeed + float(level) * 7.0;
                if (hash(vec3(c, seed)) < uSoiling) {
                    vec2 centre = c + vec2(hash(vec3(c, seed + 1.0)), hash(vec3(c, seed + 2.0)));
                    float radius = (0.3 + 0.5 * hash(vec3(c, seed + 3.0))) * (0.5 + 0.7 * uSoiling);
                    float d = length(q - centre);
                    mask = max(mask, 1.0 - smoothstep(0.75 * radius, radius, d));
                }
            }
        }
    }
    fragColour = vec4(max(mask, 0.35 * uSoiling), 0.0, 0.0, 1.0);
}
)";

/// The scene reduced by a factor f each way for the soiling's blur: each
/// texel the mean of an f x f block, from four bilinear taps f / 4 pixels
/// from its centre (uOffset, in texture coordinates).
inline constexpr const char* kLensReduceFragment = R"(
in vec2 vUv;
out vec4 fragColour;
uniform sampler2D uScene;
uniform vec2 uOffset;
void main()
{
    vec3 sum = texture(uScene, vUv + vec2(uOffset.x, uOffset.y)).rgb;
    sum += texture(uScene, vUv + vec2(-uOffset.x, uOffset.y)).rgb;
    sum += texture(uScene, vUv + vec2(uOffset.x, -uOffset.y)).rgb;
    sum += texture(uScene, vUv + vec2(-uOffset.x, -uOffset.y)).rgb;
    fragColour = vec4(0.25 * sum, 1.0);
}
)";

inline constexpr const char* kLensFragment = R"(
in vec2 vUv;
out vec4 fragColour;
uniform sampler2D uScene;
uniform vec2 uTexel;
uniform float uAspect;
uniform float uRedOut;    // 0 .. 1
#ifndef LENS_CLEAN
uniform sampler2D uMask;  // kLensMaskFragment's
uniform sampler2D uBlur;  // the scene reduced (kLensReduceFragment)
uniform float uSoiled;    // 1 with a mask to apply
uniform float uBlurRadius;  // pixels
#endif
void main()
{
    vec2 p = vec2((vUv.x * 2.0 - 1.0) * uAspect, vUv.y * 2.0 - 1.0);
    float radius = length(p);
    vec3 colour = texture(uScene, vUv).rgb;
#ifndef LENS_CLEAN
    // Soiling blurs and veils the view under its mask. The blur is a disc of
    // uBlurRadius pixels: five bilinear taps of the reduced scene, the centre
    // and four at half the radius diagonally.
    float mask = uSoiled > 0.0 ? texture(uMask, vUv).r : 0.0;
    if (mask > 0.0) {
        vec2 step = 0.5 * uBlurRadius * uTexel;
        vec3 blurred = texture(uBlur, vUv).rgb;
        blurred += texture(uBlur, vUv + vec2(step.x, step.y)).rgb;
        blurred += texture(uBlur, vUv + vec2(-step.x, step.y)).rgb;
        blurred += texture(uBlur, vUv + vec2(step.x, -step.y)).rgb;
        blurred += texture(uBlur, vUv + vec2(-step.x, -step.y)).rgb;
        blurred /= 5.0;
        vec3 veil = mix(blurred, vec3(0.62, 0.55, 0.38) * 1.6 * dot(blurred, vec3(0.33)), 0.3);
        colour = mix(colour, veil, 0.9 * mask);
    }
    // Red-out: the lens against the mucosa sees only transmitted red light.
    if (uRedOut > 0.0) {
        vec3 red = vec3(0.62, 0.06, 0.04) * (0.8 + 0.4 * fbm(vec3(p * 2.0, 7.0)));
        colour = mix(colour, red, uRedOut);
    }
#endif
    // The lens's image circle.
    colour *= 1.0 - smoothstep(0.985, 1.0, radius);
    fragColour = vec4(colour, 1.0);
}
)";

/// Coverage: triangle index + 1 in RGB where the wall is seen well enough.
inline constexpr const char* kCoverageVertex = R"(
layout(location = 0) in vec3 aPosition;
out vec3 vWorld;
void main()
{
    vec3 c;
    gl_Position = fisheye(aPosition, c);
    vWorld = aPosition;
}
)";

inline constexpr const char* kCoverageFragment = R"(
in vec3 vWorld;
out vec4 fragColour;
uniform vec3 uCameraPosition;
uniform float uWorkingDistance;
uniform float uMinCosIncidence;
void main()
{
    vec3 toCamera = uCameraPosition - vWorld;
    float distance = length(toCamera);
    vec3 n = normalize(cross(dFdx(vWorld), dFdy(vWorld)));
    float cosIncidence = abs(dot(n, toCamera / max(distance, 1e-9)));
    int id = 0;
    if (distance <= uWorkingDistance && cosIncidence >= uMinCosIncidence) {
        id = gl_PrimitiveID + 1;
    }
    fragColour = vec4(float(id & 255), float((id >> 8) & 255), float((id >> 16) & 255), 255.0) / 255.0;
}
)";

/// Scope-shape view: flat-coloured 2D triangles.
inline constexpr const char* kFlatVertex = R"(
layout(location = 0) in vec2 aPosition;
void main()
{
    gl_Position = vec4(aPosition, 0.0, 1.0);
}
)";

inline constexpr const char* kFlatFragment = R"(
out vec4 fragColour;
uniform vec4 uColour;
void main()
{
    fragColour = uColour;
}
)";

}  // namespace colonosim::render::shaders
