// Thin line emitters (laser beams) as the camera sees them: twin of
// engine/src/render/cpu/lines.rs (see there for the method and its bias). Camera rays and
// their perfect specular turns pass through line prisms and add each line prefiltered over
// the pixel's footprint. Units: metres in render space, radiance linear RGB, radians.

// Width of the prefilter's footprint in pixels (lines.rs LINE_FOOTPRINT_PIXELS).
const LINE_FOOTPRINT_PIXELS: f32 = 2.0;
// Width in traced pixels when every sample of the frame sits at one fixed offset (temporal
// upscaling: frame.pixel_jitter's bit 31; lines.rs LINE_FOOTPRINT_FIXED_OFFSET).
const LINE_FOOTPRINT_FIXED_OFFSET: f32 = 1.0;
// Line prisms a camera ray passes through before shading the prism as it is.
const MAX_LINE_CROSSINGS: u32 = 8u;
// Rays beyond this distance (metres) are cut there when measuring their distance to a line.
const LINE_FAR: f32 = 1.0e4;

// The footprint's angle across at the image's centre (radians; lines.rs pixel_angle).
fn line_pixel_angle() -> f32 {
    var pixels = LINE_FOOTPRINT_PIXELS;
    if ((frame.pixel_jitter & 0x80000000u) != 0u) {
        pixels = LINE_FOOTPRINT_FIXED_OFFSET;
    }
    return pixels * 2.0 * length(frame.camera_up) / f32(max(frame.height, 1u));
}

// Whether `hit` is on a line emitter's triangle.
fn is_line(hit: Hit) -> bool {
    let inst = instances[hit.instance];
    var material = inst.material_override;
    if (material == INVALID) {
        material = triangles[inst.triangle_base + hit.triangle].material;
    }
    return (materials[material].flags & MATERIAL_FLAG_LINE) != 0u;
}

// Whether the scene has any line emitter (the list is packed from its start).
fn has_lines() -> bool {
    return lines[0].radius > 0.0;
}

// (t, distance) of the closest approach of o + t d, t in [0, t_end] (d unit), to the segment
// a + s e, s in [0, 1] (Ericson, "Real-Time Collision Detection" 5.1.9).
fn closest_approach(o: vec3<f32>, d: vec3<f32>, t_end: f32, a: vec3<f32>, e: vec3<f32>) -> vec2<f32> {
    let r = o - a;
    let ee = dot(e, e);
    let f = dot(e, r);
    let c = dot(d, r);
    var t = 0.0;
    var s = 0.0;
    if (ee <= 1e-12) {
        t = clamp(-c, 0.0, t_end);
    } else {
        let b = dot(d, e);
        let denom = ee - b * b;
        if (denom > 1e-12) {
            t = clamp((b * f - c * ee) / denom, 0.0, t_end);
        }
        s = (b * t + f) / ee;
        if (s < 0.0) {
            s = 0.0;
            t = clamp(-c, 0.0, t_end);
        } else if (s > 1.0) {
            s = 1.0;
            t = clamp(b - c, 0.0, t_end);
        }
    }
    return vec2<f32>(t, length(o + d * t - (a + e * s)));
}

// What the camera sees of the lines along `ray` before `t_end`, prefiltered over a pixel whose
// footprint (LINE_FOOTPRINT_PIXELS pixels) at distance t is (travelled + t) * pixel_angle metres
// wide: radiance in xyz, in w the share of the footprint the line covers (what lies behind is
// weighted by 1 - w). Overlapping lines: the most covering one shows.
fn seen_lines(ray: Ray, t_end_in: f32, travelled: f32, pixel_angle: f32) -> vec4<f32> {
    let t_end = min(t_end_in, LINE_FAR);
    var seen = vec4<f32>(0.0);
    for (var i = 0u; i < MAX_LINES; i += 1u) {
        let line = lines[i];
        if (line.radius <= 0.0) {
            break;
        }
        let ct = closest_approach(ray.origin, ray.direction, t_end, line.start, line.end - line.start);
        let footprint = max((travelled + ct.x) * pixel_angle, 1e-6);
        let covered = min(ct.y + 0.5 * footprint, line.radius) - max(ct.y - 0.5 * footprint, -line.radius);
        let share = clamp(covered / footprint, 0.0, 1.0);
        if (share > seen.w) {
            seen = vec4<f32>(line.radiance.xyz * share, share);
        }
    }
    return seen;
}
