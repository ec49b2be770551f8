// The final colour of a ray (paper section 4.3), from what the earlier stages left in its image
// texel (a shaded colour, or an outcome code in alpha) and its final direction (the velocity): rays
// without a hit look the sky up by their final direction, at the bounding sphere or around a
// Schwarzschild mass at infinity. Captured and failed rays are black; a ray still travelling when
// its budget ran out shows render.unfinished_color, so that no one takes it for the sky. The sky
// stage (stage_sky.glsl) calls it on the result textures; a single-pass frame that only the image
// is read from calls it on its own results, in the same pass (FRAME_COLOUR, stage_frame.c).
uniform vec3 u_unfinished_color;
uniform float u_sky_alpha;            // render.sky_alpha: the image's alpha where rays reached the sky
#ifdef SKY_CUBEMAP
uniform samplerCube u_sky;
#else
uniform vec3 u_sky_color;
#endif
#ifdef DOPPLER_COLOUR
uniform float u_sky_temperature;      // K; 0: an RGB sky
#endif

vec3 sky(vec3 direction)
{
#ifdef SKY_CUBEMAP
    return textureCube(u_sky, direction).rgb;
#else
    return u_sky_color;
#endif
}

#ifdef TONE_MAP
// The light of an 8-bit image (src/results/tone.h, the CPU's tone_map): linear light times the
// gain, then each channel clipped at white, or (TONE_FILMIC) Narkowicz's fit of the ACES filmic
// curve on the luminance, the colour scaled with it (hue and saturation kept) and mixed toward the
// grey of its luminance only as far as brings its largest channel to white.
uniform float u_gain;

vec3 tone_map(vec3 encoded)
{
    vec3 lin = max(vec3(srgb_decode(encoded.r), srgb_decode(encoded.g), srgb_decode(encoded.b)), 0.0) * u_gain;
#ifdef TONE_FILMIC
    float l = dot(lin, vec3(0.2126, 0.7152, 0.0722));
    float mapped = l > 0.0 ? min(l * (2.51 * l + 0.03) / (l * (2.43 * l + 0.59) + 0.14), 1.0) : 0.0;
    lin = l > 0.0 ? lin * (mapped / l) : vec3(0.0);
    float top = max(lin.r, max(lin.g, lin.b));
    float toward = top > 1.0 ? (top - 1.0) / (top - mapped) : 0.0;
    lin += toward * (vec3(mapped) - lin);
#endif
    lin = clamp(lin, 0.0, 1.0);
    return vec3(srgb_encode(lin.r), srgb_encode(lin.g), srgb_encode(lin.b));
}
#endif

#ifdef GPU_STARS
// Point stars and the Milky Way in the frame's own pass (`[render] star_pass = gpu`, the kiosk):
// what the CPU's pass adds after the rays (src/results/star_light.c), from the star map
// (src/results/star_map.h) and the derivatives of the pixels' exit directions, in the same formulas.
uniform sampler2D u_star_map;
uniform vec2 u_star_map_size;           // texels: width, height
uniform float u_star_map_cells;         // cells a side at level 0
uniform float u_star_map_levels;
uniform float u_star_map_chroma_row;    // the texel row of the colours per unit luminance
uniform float u_star_map_mask_row;      // the first row of the cells' masks
uniform vec2 u_star_magnitudes;         // the faintest, and brightest minus faintest
uniform float u_star_brightness;        // the light of a 6th-magnitude star at rest
uniform float u_star_brightest_flux;    // the brightest star's, at rest
uniform float u_star_sigma;             // a star's Gaussian, pixels
uniform float u_milky_way;              // the band's radiance at its brightest; 0: none
uniform vec3 u_galactic_pole;
uniform vec3 u_galactic_x;              // longitude 0
uniform vec3 u_galactic_y;              // longitude 90 degrees

const float STAR_LIGHT_EPSILON = 2e-5;       // results/star_light.h
const float STAR_RADIUS_MAX_PX = 24.0;
const float STAR_FOOTPRINT_MAX_RAD = 0.2;
const float STAR_MAGNIFICATION_MAX = 1e4;
const int STAR_MAP_SLOTS_I = STAR_MAP_SLOTS_N;   // stars a cell (results/star_map.h, from C)
const float STAR_MAP_SLOTS = float(STAR_MAP_SLOTS_N);
const float STAR_T_MIN_K = 500.0;            // physics/blackbody.h, BLACKBODY_T_MIN_K .. MAX_K
const float STAR_T_RANGE = 4.78749174;       // ln(60000 / 500)
const float MILKY_WAY_TEMPERATURE_K = 4300.0;
// a level's cells count as this fraction of their width about the pixel's direction, so that the 3x3
// about it hold every star within the reach, also where the octahedral map skews its cells
const float STAR_CELL_MARGIN = 0.8;

vec3 star_sign(vec2 p)
{
    return vec3(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0, 0.0);
}

vec2 octahedral_encode(vec3 d)
{
    vec3 p = d / (abs(d.x) + abs(d.y) + abs(d.z));
    vec2 folded = (1.0 - abs(p.yx)) * star_sign(p.xy).xy;
    return (p.z < 0.0 ? folded : p.xy) * 0.5 + 0.5;
}

vec3 octahedral_decode(vec2 e)
{
    vec2 p = e * 2.0 - 1.0;
    float z = 1.0 - abs(p.x) - abs(p.y);
    vec2 folded = (1.0 - abs(p.yx)) * star_sign(p).xy;
    return normalize(vec3(z < 0.0 ? folded : p, z));
}

// linear colour per unit luminance of the black body at step `code` of the map's last row (its
// temperatures run from STAR_T_MIN_K up in 255 steps of ln(T) to 60000 K), the nearest step
vec3 star_chroma_at(float code)
{
    float k = clamp(floor(code + 0.5), 0.0, 255.0);
    vec3 c = texture2D(u_star_map, vec2(k + 0.5, u_star_map_chroma_row + 0.5) / u_star_map_size).rgb;
    return c / dot(c, vec3(0.2126, 0.7152, 0.0722));
}

// the same of a black body of temperature t
vec3 star_chroma(float t)
{
    return star_chroma_at(log(t / STAR_T_MIN_K) / STAR_T_RANGE * 255.0);
}

// The band of the Milky Way along d relative to its brightest (star_light.c, milky_way_shape).
float milky_way_shape(vec3 d)
{
    float z = dot(d, u_galactic_pole);
    if (abs(z) > 0.8134)
        return 0.0;
    float b = asin(clamp(z, -1.0, 1.0));
    float l = atan(dot(d, u_galactic_y), dot(d, u_galactic_x));
    float towards_centre = 0.5 + 0.5 * cos(l);
    float disk = exp(-0.5 * (b / 0.10) * (b / 0.10)) * (0.35 + 0.65 * towards_centre * towards_centre);
    float bulge = 0.8 * exp(-0.5 * ((b / 0.18) * (b / 0.18) + (l / 0.35) * (l / 0.35)));
    float dust = 1.0 - 0.55 * exp(-0.5 * (b / 0.025) * (b / 0.025)) * towards_centre;
    float clouds = 1.0 + 0.2 * cos(5.0 * l + 0.7) + 0.15 * cos(11.0 * l + 2.1);
    return (disk + bulge) * dust * clouds / 1.8;
}

// The light of the stars and the band along exit direction d, linear: jx, jy the change of d per
// pixel step (the footprint J), fx, fy the same of the camera's straight rays; doppler the view
// direction's Doppler factor (1 without the colour effects), searchlight whether the light scales
// with it. A star at angular offset t from d lies J+ t pixels from the pixel's centre (J+ the
// least-squares inverse), its flux times the magnification |det J_flat| / |det J|.
vec3 sky_stars(vec3 d, vec3 jx, vec3 jy, vec3 fx, vec3 fy, float doppler, bool searchlight)
{
    vec3 light = vec3(0.0);
    float band = u_milky_way > 0.0 ? milky_way_shape(d) : 0.0;
    float d4 = doppler * doppler * doppler * doppler;
    light += u_milky_way * band * (searchlight ? d4 : 1.0) * star_chroma(MILKY_WAY_TEMPERATURE_K * doppler);
    float xx = dot(jx, jx);
    float xy = dot(jx, jy);
    float yy = dot(jy, jy);
    float det = xx * yy - xy * xy;
    if (!(det > 0.0))
        return light;
    float magnification = min(length(cross(fx, fy)) / sqrt(det), STAR_MAGNIFICATION_MAX);
    float gain = magnification * (searchlight ? doppler * doppler : 1.0);
    float sigma = u_star_sigma;
    float spread = 1.0 / (6.28318531 * sigma * sigma);
    float peak = u_star_brightest_flux * gain * spread;
    if (!(peak >= STAR_LIGHT_EPSILON))
        return light;
    float reach_px = min(sigma * sqrt(2.0 * log(peak / STAR_LIGHT_EPSILON)), STAR_RADIUS_MAX_PX);
    float trace = xx + yy;
    float widest = sqrt(0.5 * (trace + sqrt(max(trace * trace - 4.0 * det, 0.0))));
    // at most STAR_FOOTPRINT_MAX_RAD (results/star_light.h)
    float reach = min(reach_px * widest, STAR_FOOTPRINT_MAX_RAD);
    if (!(reach > 0.0))
        return light;
    // the width of the map's level-0 cells about d (the octahedral map's cells differ in size and
    // shape, fourfold from its centre to its folds): the least of the three sides of the triangle
    // of cell centres, chords as angles
    vec2 corner = clamp(floor(octahedral_encode(d) * u_star_map_cells), 0.0, u_star_map_cells - 2.0) + 0.5;
    vec3 c0 = octahedral_decode(corner / u_star_map_cells);
    vec3 c1 = octahedral_decode((corner + vec2(1.0, 0.0)) / u_star_map_cells);
    vec3 c2 = octahedral_decode((corner + vec2(0.0, 1.0)) / u_star_map_cells);
    float width = min(min(length(c1 - c0), length(c2 - c0)), length(c2 - c1));
    // the level whose cells are as wide as the reach, and the 3x3 of its cells about d
    float level = max(ceil(log2(reach / (width * STAR_CELL_MARGIN))), 0.0);
    if (level >= u_star_map_levels)
        return light;
    float n = floor(u_star_map_cells / exp2(level) + 0.5);
    vec2 origin = level < 0.5 ? vec2(0.0) : vec2(2.0 * STAR_MAP_SLOTS * (u_star_map_cells - 2.0 * n), u_star_map_cells);
    vec2 centre = clamp(floor(octahedral_encode(d) * n), 0.0, n - 1.0);
    vec2 base = centre - 1.0;
    // which of the nine cells hold a star: bit 8 - k for cell k (results/star_map.h), so that the
    // highest bit left is the next cell in the order of k
    vec2 mask_origin = vec2(level < 0.5 ? 0.0 : 2.0 * (u_star_map_cells - n), u_star_map_mask_row);
    vec4 mask = floor(texture2D(u_star_map, (mask_origin + centre + 0.5) / u_star_map_size) * 255.0 + 0.5);
    float occupied = mask.x + 256.0 * mask.y;
    vec3 inverse = vec3(yy, -xy, xx) / det;
    float reach_cos = cos(reach);
    // a star's light at the pixel in one exp2: log2 of its flux (from its magnitude, 16 bits over the
    // catalogue's range) times the gain and the Gaussian's peak, less its offset's share; and the
    // step of its colour's row moved by the Doppler factor (its temperature's code is ln(T) in steps)
    float log2_light = log2(u_star_brightness * gain * spread) - 1.32877124 * (u_star_magnitudes.x - 6.0);
    float log2_per_code = -1.32877124 * u_star_magnitudes.y / 65535.0;
    float log2_per_px2 = -0.72134752 / (sigma * sigma);
    float doppler_codes = log(doppler) / STAR_T_RANGE * 255.0;
    // one loop over the cells of the nine that hold a star, in the order of k
    for (int k = 0; k < 9; k++) {
        if (occupied < 0.5)
            break;
        {
            // the highest bit left: log2's estimate, made exact (its rounding may miss by one)
            float top = floor(log2(occupied));
            top += occupied >= exp2(top + 1.0) ? 1.0 : 0.0;
            top -= occupied < exp2(top) ? 1.0 : 0.0;
            occupied -= exp2(top);
            float cell_k = 8.0 - top;
            float j = floor((cell_k + 0.5) / 3.0);
            vec2 cell = base + vec2(cell_k - 3.0 * j, j);
            // across the square's border, the map folds back onto itself mirrored
            cell = cell.x < 0.0 ? vec2(0.0, n - 1.0 - cell.y) : cell.x > n - 1.0 ? vec2(n - 1.0, n - 1.0 - cell.y) : cell;
            cell = cell.y < 0.0 ? vec2(n - 1.0 - cell.x, 0.0) : cell.y > n - 1.0 ? vec2(n - 1.0 - cell.x, n - 1.0) : cell;
            vec2 first = origin + vec2(2.0 * STAR_MAP_SLOTS * cell.x, cell.y) + 0.5;
            for (int slot = 0; slot < STAR_MAP_SLOTS_I; slot++) {
                vec2 texel = first + vec2(2.0 * float(slot), 0.0);
                vec4 data = floor(texture2D(u_star_map, (texel + vec2(1.0, 0.0)) / u_star_map_size) * 255.0 + 0.5);
                // the slots fill in order, brightest first: an empty one ends the cell
                if (data.w < 127.0)
                    break;
                vec4 place = floor(texture2D(u_star_map, texel / u_star_map_size) * 255.0 + 0.5);
                vec2 within = (vec2(place.x * 256.0 + place.y, place.z * 256.0 + place.w) + 0.5) / 65536.0;
                vec3 s = octahedral_decode((cell + within) / n);
                float along = dot(s, d);
                if (along <= 0.0 || along < reach_cos)
                    continue;
                vec3 t = s / along - d;
                float rx = dot(jx, t);
                float ry = dot(jy, t);
                float px = inverse.x * rx + inverse.y * ry;
                float py = inverse.y * rx + inverse.z * ry;
                float value = exp2(log2_light + log2_per_code * (data.x * 256.0 + data.y) + log2_per_px2 * (px * px + py * py));
                if (!(value >= STAR_LIGHT_EPSILON))
                    continue;
                light += value * star_chroma_at(data.z + doppler_codes);
            }
        }
    }
    return light;
}
#endif

#ifdef STAR_FOOTPRINT_NEIGHBOURS
// A pixel's footprints (the Jacobians of its exit direction and of the camera's straight ray per
// pixel step) from its neighbouring rays, where the GPU takes no derivatives: the pass that includes
// this file reads the rays' state and defines it (stage_sky.glsl).
void star_footprints(out vec3 jx, out vec3 jy, out vec3 fx, out vec3 fy);
#endif

// image: colour and outcome code (common.glsl); velocity: the final direction, any length.
vec4 sky_final_colour(vec4 image, vec3 velocity)
{
    vec3 color = image.rgb;
    float alpha = image.a == CODE_SKY ? u_sky_alpha : 1.0;
#ifdef GPU_STARS
    vec3 exit_direction = normalize(velocity);
#ifdef STAR_FOOTPRINT_NEIGHBOURS
    // from the neighbouring rays, which the pass reads (stage_sky.glsl: a GPU without derivatives)
    vec3 footprint_x, footprint_y, straight_x, straight_y;
    star_footprints(footprint_x, footprint_y, straight_x, straight_y);
#else
    // the footprints, before any branch: the derivatives are differences across the 2x2 group of
    // fragments, which all take them here
    vec3 footprint_x = dFdx(exit_direction);
    vec3 footprint_y = dFdy(exit_direction);
    vec3 straight = observer_scene_direction(observer_view_direction());
    vec3 straight_x = dFdx(straight);
    vec3 straight_y = dFdy(straight);
#endif
#endif
    if (image.a == CODE_SKY) {
        color = sky(normalize(velocity));
#ifdef DOPPLER_COLOUR
        // the sky rests at infinity (lapse 1)
        float doppler = observer_doppler(observer_view_direction()) / u_observer_lapse;
        vec3 black_body = rgb_luminance(color) * blackbody_colour(u_sky_temperature * doppler);
#ifdef SEARCHLIGHT
        vec3 rgb = color * (doppler * doppler * doppler * doppler);
#else
        vec3 rgb = color;
#endif
        color = u_sky_temperature > 0.0 ? black_body : rgb;
#endif
#ifdef GPU_STARS
        // added to the sky's colour in linear light, as the CPU's pass adds them to the image
#ifdef DOPPLER_COLOUR
        float star_doppler = observer_doppler(observer_view_direction()) / u_observer_lapse;
#else
        float star_doppler = 1.0;
#endif
#ifdef SEARCHLIGHT
        bool searchlight = true;
#else
        bool searchlight = false;
#endif
        vec3 stars = sky_stars(exit_direction, footprint_x, footprint_y, straight_x, straight_y, star_doppler,
                               searchlight);
        vec3 sum = vec3(srgb_decode(color.r), srgb_decode(color.g), srgb_decode(color.b)) +
                   stars;
        vec3 lit = vec3(srgb_encode(sum.r), srgb_encode(sum.g), srgb_encode(sum.b));
        color = stars.r + stars.g + stars.b > 0.0 ? lit : color;
#endif
    }
    else if (image.a == CODE_UNFINISHED)
        color = u_unfinished_color;
    else if (image.a < -0.5)
        color = vec3(0.0);
#ifdef HDR_OUTPUT
    // a float target (16-bit PNG, PFM): the colour as shaded, brighter than white where it is
    return vec4(max(color, 0.0), alpha);
#else
#ifdef TONE_MAP
    color = tone_map(color);
#endif
    return vec4(clamp(color, 0.0, 1.0), alpha);
#endif
}

#ifdef FRAME_CODES
// Beside the final colour, for a summary of the frame (FRAME_WRITES_COLOUR_CODES, stage_frame.c),
// in an 8-bit target: in r the ray's outcome code (its image texel's alpha: an object's id, 0 to
// 63, or a code of common.glsl down to CODE_FAILED) plus 4, in g how many of the texel's four
// values the 32-bit float image texture would carry as not finite (beyond its largest finite
// value; NaN fails the test too). Each count is written a quarter above its byte, so that a
// driver that rounds and one that truncates store the same byte. On 32-bit paths only
// (renderer.c, run_single_pass).
float not_held(float x)
{
    return abs(x) <= 3.4028235e38 ? 0.0 : 1.0;
}

vec4 outcome_code_bytes(vec4 image)
{
    float bad = not_held(image.r) + not_held(image.g) + not_held(image.b) + not_held(image.a);
    return vec4((image.a + 4.25) / 255.0, (bad + 0.25) / 255.0, 0.0, 1.0);
}
#define WRITE_FRAME_COLOUR(image, direction) WRITE_TARGET0(sky_final_colour(image, direction)); WRITE_TARGET1(outcome_code_bytes(image))
#else
#define WRITE_FRAME_COLOUR(image, direction) WRITE_TARGET0(sky_final_colour(image, direction))
#endif
