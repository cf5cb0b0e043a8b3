#!/usr/bin/env python3
"""Writes assets/its_about_time/ruins.ron: the ruins' layout laid out in code (walls coursed from
the kit's sandstone blocks, the dune ring, the sun gate's shrine with its slot aimed at the sun).

Run from the repository root: python3 games/its_about_time/layout/ruins_layout.py
The written file is the level; edit this script (or the level in the F1 editor) and re-record the
replay (cargo run --release -p its_about_time --example record_replay). Metres, degrees; x east,
y up, z south (north is -Z)."""
import math, pathlib

OUT = pathlib.Path("assets/its_about_time/ruins.ron")
inst = []

def add(model, x, y, z, name=None, rot=(0, 0, 0), scale=None, body="Static(shape: Box)", dynamic=False):
    s = f'(model: "{model}"'
    if name:
        s += f', name: "{name}"'
    t = f"translation: ({x:g}, {y:g}, {z:g})"
    if rot != (0, 0, 0):
        t += f", rotation_deg: ({rot[0]:g}, {rot[1]:g}, {rot[2]:g})"
    if scale:
        t += f", scale: ({scale[0]:g}, {scale[1]:g}, {scale[2]:g})"
    s += f", transform: ({t})"
    if dynamic:
        s += ", dynamic: true"
    if body:
        s += f", body: {body}"
    inst.append(s + "),")

BLOCK = {"block_large": (2.4, 1.2, 1.2), "block_medium": (1.6, 0.8, 0.8), "block_small": (1.0, 0.5, 0.6)}

def wall(x0, z0, x1, z1, courses, block="block_large", skip=None, prefix=None):
    """A wall of `courses` courses of blocks from (x0, z0) to (x1, z1) (axis-aligned), every other
    course set half a block along; `skip(s, y)` leaves out blocks whose centre is at distance s
    along the wall and height y (a doorway)."""
    bx, by, bz = BLOCK[block]
    length = abs(x1 - x0) + abs(z1 - z0)
    along_x = abs(x1 - x0) > abs(z1 - z0)
    n = max(1, round(length / bx))
    step = length / n
    sx = step / bx
    for c in range(courses):
        offset = 0.5 * step if c % 2 else 0.0
        k = 0
        while True:
            s0 = k * step - offset
            if s0 >= length - 1e-6:
                break
            a, b = max(0.0, s0), min(length, s0 + step)
            k += 1
            if b - a < 0.3:
                continue
            mid = (a + b) / 2
            y = c * by
            if skip and skip(mid, y + by / 2):
                continue
            scale_len = (b - a) / bx
            if along_x:
                x = min(x0, x1) + mid
                add(block, x, y, z0, scale=(scale_len, 1, 1) if abs(scale_len - 1) > 1e-3 else None)
            else:
                z = min(z0, z1) + mid
                add(block, x0, y, z, rot=(0, 90, 0), scale=(scale_len, 1, 1) if abs(scale_len - 1) > 1e-3 else None)

def column(x, z, drums=3):
    for d in range(drums):
        add("column_drum", x, d, z)
    add("column_capital", x, drums, z)

# --- The temple to the north: three tiers, steps, carved panels, torches, its altar.
TZ = -26
for i, (scale, y) in enumerate([(1.6, 0.0), (1.2, 1.5), (0.8, 3.0)]):
    add("temple_tier", 0, y, TZ, scale=(scale, 1, scale))
for i, (x, y) in enumerate([(-2.2, 0.0), (2.2, 0.0)]):
    add("carved_panel", x, 0, TZ + 6.4 + 0.3)
add("steps", 0, 0, TZ + 6.4 + 1.35)
add("sun_altar", 0, 0, -14, name="temple_altar_stone")
add("sensor", 0, 1, -14, name="temple_altar",
    body="Sensor(shape: Cuboid(half_extents: (2.2, 1.5, 2.2)))")
for x in (-3.2, 3.2):
    column(x, -14)
add("lintel", 0, 4.0, -14, scale=(2.0, 1, 1))
for x in (-5.5, 5.5):
    add("torch", x, 0, -15)
    add("torch_flame", x, 1.5, -15, body=None)
add("glyph_tile", -1.6, 0.0, -18.5)
add("glyph_glow_0", -1.6, 0.0, -18.5, body=None)
add("glyph_tile", 1.6, 0.0, -18.5)
add("glyph_glow_2", 1.6, 0.0, -18.5, body=None)

# --- A colonnade along the way from the start to the temple.
for z in (2, -4):
    for x in (-4.5, 4.5):
        column(x, z, 3 if z == 2 else 2)
add("lintel", -4.5, 3.0, 3.2, rot=(0, 90, 0), scale=(1, 1, 1))

# --- The sun altar, where time turns.
add("sun_altar", 5, 0, 5, name="sun_altar")
add("sun_disc", 5, 1.45, 5, rot=(90, -60, 0), body=None)

# --- The shrine of the sun glyph: a closed stone room (3 x 3 m inside) whose only opening is a
# slot in its west wall, aimed at where the sun stands at about 15:15 local time on 21 March
# (azimuth 254.5 deg, elevation 38 deg at 19.69 N, 98.84 W). Inside, the glyph (a sensor: the
# rule `sun_gate` holds while SunLit("sun_glyph")).
GX, GZ = 12.0, 0.0
W0, W1 = 9.5, 12.8         # inner faces west / east
N0, N1 = -1.5, 1.5         # inner faces north / south
T = 0.3                    # wall thickness
H = 2.9                    # wall height
sun = (-0.759, 0.616, 0.2106)
t = (GX - W0) / -sun[0]
slot_z = GZ + sun[2] * t
slot_y = 0.01 + sun[1] * t
SW, SH = 0.7, 0.9          # slot width (z) and height (y)
def box_piece(x0, x1, y0, y1, z0, z1):
    bx, by, bz = BLOCK["block_large"]
    add("block_large", (x0 + x1) / 2, y0, (z0 + z1) / 2,
        scale=((x1 - x0) / bx, (y1 - y0) / by, (z1 - z0) / bz))
zs0, zs1 = slot_z - SW / 2, slot_z + SW / 2
ys0, ys1 = slot_y - SH / 2, slot_y + SH / 2
# West wall in four pieces round the slot.
box_piece(W0 - T, W0, 0, H, N0 - T, zs0)
box_piece(W0 - T, W0, 0, H, zs1, N1 + T)
box_piece(W0 - T, W0, 0, ys0, zs0, zs1)
box_piece(W0 - T, W0, ys1, H, zs0, zs1)
box_piece(W1, W1 + T, 0, H, N0 - T, N1 + T)   # east
box_piece(W0, W1, 0, H, N0 - T, N0)           # north
box_piece(W0, W1, 0, H, N1, N1 + T)           # south
box_piece(W0 - T - 0.2, W1 + T + 0.2, H, H + 0.4, N0 - T - 0.2, N1 + T + 0.2)  # roof
add("glyph_tile", GX, 0.01, GZ, name="sun_glyph",
    body="Sensor(shape: Cuboid(half_extents: (0.5, 0.3, 0.5)))")
add("glyph_glow_0", GX, 0.01, GZ, body=None)

# --- The gate court east of the shrine: walls of coursed blocks, the sun gate in the west
# wall, the Sun Disc on a pedestal inside.
CX0, CX1, CZ0, CZ1 = 16.0, 26.0, -6.0, 6.0
door = lambda s, y: abs(s - (0 - CZ0)) < 1.6 and y < 3.3
wall(CX0, CZ0, CX0, CZ1, 3, skip=door)
wall(CX1, CZ0, CX1, CZ1, 3)
wall(CX0, CZ0, CX1, CZ0, 3)
wall(CX0, CZ1, CX1, CZ1, 3)
add("lintel", CX0, 3.0, 0, rot=(0, 90, 0), scale=(1.2, 1, 1))
add("carved_panel", CX0 - 0.6, 0, 0, name="sun_gate", rot=(0, 90, 0), scale=(1.5, 1.5, 1),
    dynamic=True, body="Kinematic(shape: Box)")
add("block_medium", 22, 0, 0, name="pedestal")
add("sun_disc", 22, 1.3, 0, name="artifact_sun", rot=(90, -90, 0),
    dynamic=True, body="Kinematic(shape: Box)")
add("torch", 24.5, 0, -4.5)
add("torch_flame", 24.5, 1.5, -4.5, body=None)
add("torch", 24.5, 0, 4.5)
add("torch_flame", 24.5, 1.5, 4.5, body=None)

# --- Fallen stones and low ruined walls about the plaza.
wall(-14, 6, -8, 6, 2, block="block_medium")
wall(-14, -6, -14, 6, 1, block="block_medium")
for (x, z, r) in [(-9, 10, 20), (8, 12, -35), (-12, -10, 10), (12, -12, 65), (-20, 2, 0)]:
    add("block_medium", x, 0, z, rot=(0, r, 0))
add("block_large", -16, 0, -18, rot=(0, 15, 0))
add("block_large", -16, 1.2, -18.3, rot=(0, 40, 0))
add("boulder", 18, 0.85, 14, rot=(10, 30, 0))
for (x, z) in [(-10, -2), (-10, -8)]:
    column(x, z, 1)

# --- The sand: a flat plaza and a ring of dunes round it (40 m tiles).
add("plaza", 0, -0.2, 0)
for tx in (-60, -20, 20, 60):
    for tz in (-60, -20, 20, 60):
        if abs(tx) > 45 or abs(tz) > 45:
            add("sand_terrain", tx, -0.25, tz, body="Static(shape: Trimesh)")

PIECES = ["block_large", "block_medium", "block_small", "steps", "column_drum", "column_capital",
          "carved_panel", "lintel", "temple_tier", "torch", "torch_flame", "sun_altar", "sun_disc",
          "glyph_tile", "glyph_glow_0", "glyph_glow_2", "boulder", "sand_terrain"]
models = "\n".join(f'        (name: "{p}", path: "its_about_time/kit/{p}.gltf"),' for p in PIECES)

level = f"""// It's About Time: the ruins (first slice: the temple, the sun altar and the sun gate; the other
// four puzzles follow). Written by games/its_about_time/layout/ruins_layout.py from the kit made by
// `cargo run --release -p assetgen -- ruins-kit`; the explorer is assets/common/hero/hero.glb.
// The replay assets/its_about_time/replays/full_game.replay carries this file's hash: re-record it
// after a change (cargo run --release -p its_about_time --example record_replay).
// Metres, seconds, degrees; x east, y up, z south (north is -Z). 19.69 N, 98.84 W, 21 March.
Level(
    models: [
{models}
    ],
    materials: [
        (name: "hidden", kind: Diffuse, base_color: (0.1, 0.1, 0.1)),
        (name: "plaza_sand", kind: Diffuse, base_color: (0.62, 0.47, 0.31)),
    ],
    boxes: [
        // A trigger volume's body: the volume is its sensor shape; the box itself is a speck.
        (name: "sensor", size: (0.001, 0.001, 0.001), material: "hidden"),
        (name: "plaza", size: (90, 0.4, 90), material: "plaza_sand"),
    ],
    instances: [
        {chr(10).join('        ' + i for i in inst).lstrip()}
    ],
    camera: (position: (0, 3, 17), look_at: (0, 1.2, 8), vertical_fov_deg: 60),
    sky: Physical((
        time: Some((latitude_deg: 19.69, longitude_deg: -98.84, year: 2026, month: 3, day: 21, utc_hours: 15.5)),
        haze: 6,
        ground_albedo: (0.45, 0.36, 0.26),
    )),
    render: (max_bounces: 2, roulette_start: 1),
    characters: [(
        name: "explorer",
        model: "common/hero/hero.glb",
        scale: 1,
        model_yaw_deg: 180,
        spawn: (0, 0, 12),
        capsule: (height: 1.8, radius: 0.3),
        controller: (walk_speed: 2, run_speed: 5, jump_speed: 4),
        states: [
            (name: "jump", clip: "jump", mode: Loop, contact: Rising, fade_seconds: 0.1),
            (name: "fall", clip: "fall", mode: Loop, contact: Falling, fade_seconds: 0.2),
            (name: "idle", clip: "idle", contact: Grounded, max_speed_mps: 0.3),
            (name: "walk", clip: "walk", contact: Grounded, min_speed_mps: 0.3, max_speed_mps: 3.5,
                reference_speed_mps: 1.45),
            (name: "run", clip: "run", contact: Grounded, min_speed_mps: 3.5,
                reference_speed_mps: 3.35),
        ],
    )],
    gameplay: (
        sounds: [
            (name: "chime", path: "common/sounds/chime.wav"),
            (name: "door", path: "common/sounds/door_slide.wav"),
        ],
        animations: [
            (name: "gate_open", tracks: [(target: "sun_gate", property: Translation, interpolation: Linear,
                keys: [(time_seconds: 0, value: [{CX0 - 0.6:g}, 0, 0]), (time_seconds: 2, value: [{CX0 - 0.6:g}, 3.4, 0])])]),
            (name: "artifact_sun_taken", tracks: [(target: "artifact_sun", property: Translation, interpolation: Linear,
                keys: [(time_seconds: 0, value: [22, 1.3, 0]), (time_seconds: 1, value: [22, -1, 0])])]),
        ],
        volumes: [
            (name: "sun_glyph", instance: "sun_glyph", detects: [Player]),
            (name: "temple_altar", instance: "temple_altar", detects: [Player]),
        ],
        counters: [(name: "artifacts")],
        events: ["sun_altar", "artifact_sun"],
        usables: [
            (instance: "sun_altar", prompt: "Hold Q or R to turn time", event: "sun_altar"),
            (instance: "artifact_sun", prompt: "E  take the Sun Disc", event: "artifact_sun"),
        ],
        rules: [
            // E at the altar only rings it; holding Q or R there turns time (the game does that).
            (name: "altar_rung", when: Event("sun_altar"), then: [Sound(sound: "chime", at: "sun_altar", volume: 0.4)]),
            (name: "sun_gate", when: SunLit("sun_glyph"),
                then: [Play(clip: "gate_open"), Sound(sound: "door", at: "sun_gate")],
                otherwise: [Reverse(clip: "gate_open"), Sound(sound: "door", at: "sun_gate")]),
            (name: "take_sun", when: Event("artifact_sun"),
                then: [Count(counter: "artifacts"), Play(clip: "artifact_sun_taken"), Sound(sound: "chime")],
                once: true),
            (name: "ending", when: All([Occupied("temple_altar"), Counter(counter: "artifacts", at_least: 1)]),
                then: [Sound(sound: "chime"), Win], once: true),
        ],
    ),
)
"""
OUT.write_text(level)
print(f"wrote {OUT}: {len(inst)} instances; slot centre z {slot_z:.2f} y {slot_y:.2f}")
