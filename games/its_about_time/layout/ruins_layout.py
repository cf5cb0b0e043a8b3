#!/usr/bin/env python3
"""Writes assets/its_about_time/ruins.ron: the ruins' layout laid out in code (walls coursed from
the kit's sandstone blocks, the dune ring, the sun gate's shrine with its slot aimed at the sun).

Run from the repository root: python3 games/its_about_time/layout/ruins_layout.py
The written file is the level; edit this script (or the level in the F1 editor) and re-record the
replay (cargo run --release -p its_about_time --example record_replay). Metres, degrees; x east,
y up, z south (north is -Z)."""
import math
import pathlib

import sys

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from kit import (BLOCK, add, area, area_group, artifact_rules, box_piece, boxes, breakables, clip, clips,
                 column, counters, events, grids, inst, lights_off, materials, render_areas, rules, usables,
                 volumes, wall)
import puzzles

OUT = pathlib.Path("assets/its_about_time/ruins.ron")

# --- Render areas (`render_areas`): one per puzzle and the temple, each with its emitters in a
# light group of its own (1 temple, 2 sun gate, 3 water stair, 4 weights, 5 rolling stone,
# 6 night shrine; the shrine's torches are 11-14); the camera inside an area samples only the
# groups it lists, which must be every group that can light what the camera sees from the box
# (the plaza is open: most are), else those emitters show as fireflies. The test
# `games/its_about_time/tests/render_areas.rs` checks the lists and names a group missing. Each
# box holds its puzzle's camera way (`its_about_time --replay R --headless --camera-path OUT`),
# the sun gate's the plaza's sun altar where time is turned. The plaza's south, where play
# starts, is in no area: every group is sampled there. Y spans the follow camera's heights
# (metres).
Y0, Y1 = -1, 15
# --- The temple to the north: three tiers, steps, carved panels, torches, its altar.
area("temple", 1, (-12, Y0, -36), (12, Y1, -8), [1, 2, 3, 4, 6, 11, 12, 13, 14])
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
for x, side in ((-5.5, "west"), (5.5, "east")):
    add("torch", x, 0, -15)
    add("torch_flame", x, 1.5, -15, name=f"temple_torch_{side}", body=None)
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

area("sun_gate", 2, (0, Y0, -7), (27, Y1, 12), [1, 2, 3, 4, 6, 12, 14])
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
# wall, the Sun Disc standing on a pedestal inside, its face to the gate.
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
add("sun_disc", 22, 1.3, 0, name="artifact_sun", rot=(0, 90, 0),
    dynamic=True, body="Kinematic(shape: Box)")
add("torch", 24.5, 0, -4.5)
add("torch_flame", 24.5, 1.5, -4.5, name="gate_torch_north", body=None)
add("torch", 24.5, 0, 4.5)
add("torch_flame", 24.5, 1.5, 4.5, name="gate_torch_south", body=None)

# --- The puzzles after the sun gate (puzzles.py).
puzzles.water_stair()
puzzles.weights()
puzzles.rolling_stone()
puzzles.night_shrine()
area_group[0] = None

# --- Fallen stones and low ruined walls about the plaza (clear of the puzzles' ways).
wall(-14, 6, -8, 6, 2, block="block_medium")
wall(-14, -6, -14, 6, 1, block="block_medium")
for (x, z, r) in [(8, 12, -35), (-12, -10, 10), (12, -12, 65), (-6, 20, 30)]:
    add("block_medium", x, 0, z, rot=(0, r, 0))
add("block_large", -16, 0, -18, rot=(0, 15, 0))
add("block_large", -16, 1.2, -18.3, rot=(0, 40, 0))
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
          "glyph_tile", "glyph_glow_0", "glyph_glow_1", "glyph_glow_2", "glyph_glow_3", "boulder",
          "sand_terrain", "lever_base", "lever_handle", "pressure_plate", "pressure_plate_frame",
          "push_block"] + [f"brittle_wall_piece_{i}" for i in range(9)]
models = "\n".join(f'        (name: "{p}", path: "its_about_time/kit/{p}.gltf"),' for p in PIECES)


def block(name, items):
    body = "\n".join("            " + i for i in items)
    return f"        {name}: [\n{body}\n        ],"


# The sun gate and the artifact it guards (the first puzzle, laid out above).
clip("gate_open", "sun_gate", "Translation", [(0, [0, 0, 0]), (2, [0, 3.4, 0])])
clip("artifact_sun_taken", "artifact_sun", "Translation", [(0, [0, 0, 0]), (1, [0, -2.3, 0])])
volumes[:0] = ['(name: "sun_glyph", instance: "sun_glyph", detects: [Player]),',
               '(name: "temple_altar", instance: "temple_altar", detects: [Player]),']
events[:0] = ["sun_altar", "artifact_sun"]
usables[:0] = ['(instance: "sun_altar", prompt: "Hold Q or R to turn time", event: "sun_altar"),',
               '(instance: "artifact_sun", prompt: "E  take the Sun Disc", event: "artifact_sun"),']
ARTIFACTS = 5
rules[:0] = [
    '// E at the altar only rings it; holding Q or R there turns time (the game does that).',
    '(name: "altar_rung", when: Event("sun_altar"), then: [Sound(sound: "altar_gong", at: "sun_altar", volume: 0.5)]),',
    '(name: "sun_gate", when: SunLit("sun_glyph"), then: [Play(clip: "gate_open"), Sound(sound: "stone_scrape", at: "sun_gate")], '
    'otherwise: [Reverse(clip: "gate_open"), Sound(sound: "stone_scrape", at: "sun_gate")]),',
    '(name: "take_sun", when: Event("artifact_sun"), then: [Count(counter: "artifacts"), Play(clip: "artifact_sun_taken"), '
    'Sound(sound: "artifact_chime")], once: true),',
]
rules.append(f'(name: "ending", when: All([Occupied("temple_altar"), Counter(counter: "artifacts", at_least: {ARTIFACTS})]), '
             'then: [Sound(sound: "temple_awake"), Win], once: true),')
counters[:0] = ['(name: "artifacts"),']
event_list = ", ".join(f'"{e}"' for e in events)
# Sounds made by `cargo run --release -p assetgen -- ruins-sounds` (the game plays the footsteps
# and the loops: games/its_about_time/src/game/soundscape.rs); every sound is the game's own.
RUINS_SOUNDS = ["altar_gong", "artifact_chime", "pad_day", "pad_night", "sluice", "stone_scrape",
                "temple_awake", "time_warp", "torch", "torch_douse", "torch_ignite", "water", "wind"]
RUINS_SOUNDS += [f"footstep_{s}_{k}" for s in ("sand", "stone") for k in (1, 2, 3)]
sound_list = "\n".join(f'            (name: "{n}", path: "its_about_time/sounds/{n}.wav"),'
                        for n in RUINS_SOUNDS)
# Loops at always-lit torches and, once the level has it, at the pool.
emitters = [f'(instance: "{t}", sound: "torch", volume: 0.5),' for t in
            ("temple_torch_west", "temple_torch_east", "gate_torch_north", "gate_torch_south")]
if any('name: "pool"' in i for i in inst):
    emitters.append('(instance: "pool", sound: "water", volume: 0.8),')

level = f"""// It's About Time: the ruins: the temple, the sun altar, the sun gate, the court of weights,
// the water stair, the rolling stone and the night shrine. Written by
// games/its_about_time/layout/ruins_layout.py (with kit.py and puzzles.py) from the kit made by
// `cargo run --release -p assetgen -- ruins-kit`; the explorer is assets/common/hero/hero.glb.
// The replays in assets/its_about_time/replays/ carry this file's hash: re-record them after a
// change (cargo run --release -p its_about_time --example record_replay).
// Metres, seconds, degrees; x east, y up, z south (north is -Z). 19.69 N, 98.84 W, 21 March.
Level(
    models: [
{models}
    ],
    materials: [
        (name: "hidden", kind: Diffuse, base_color: (0.1, 0.1, 0.1)),
        (name: "plaza_sand", kind: Diffuse, base_color: (0.62, 0.47, 0.31)),
        (name: "jade", kind: MetalRough, base_color: (0.12, 0.42, 0.26), roughness: 0.25),
        (name: "obsidian", kind: MetalRough, base_color: (0.03, 0.03, 0.035), roughness: 0.1),
        (name: "silver", kind: Conductor, base_color: (0.93, 0.93, 0.95), roughness: 0.08),
{chr(10).join('        ' + m for m in materials)}
    ],
    boxes: [
        // A trigger volume's body: the volume is its sensor shape; the box itself is a speck.
        (name: "sensor", size: (0.001, 0.001, 0.001), material: "hidden"),
        (name: "plaza", size: (90, 0.4, 90), material: "plaza_sand"),
{chr(10).join('        ' + b for b in boxes)}
    ],
    grids: [
{chr(10).join('        ' + g for g in grids)}
    ],
    instances: [
{chr(10).join('        ' + i for i in inst)}
    ],
    camera: (position: (0, 3, 17), look_at: (0, 1.2, 8), vertical_fov_deg: 60),
    sky: Physical((
        time: Some((latitude_deg: 19.69, longitude_deg: -98.84, year: 2026, month: 3, day: 21, utc_hours: 15.5)),
        haze: 6,
        ground_albedo: (0.45, 0.36, 0.26),
    )),
    // Workload scaling holds 30 fps down to a quarter of the window per axis (320×180 of
    // 1280×720), as Reflect's chambers do. No Russian roulette within the two bounces: from the
    // first bounce it ended half the paths off the shaded sandstone and doubled the rest, whose
    // bounce onto sunlit sand then showed as orange dots (docs/PERFORMANCE.md, issue 36).
    render: (max_bounces: 2, roulette_start: 2, target_fps: 30, min_scale: 0.25),
    render_areas: [
{chr(10).join('        ' + a for a in render_areas)}
    ],
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
{sound_list}
        ],
{block("emitters", emitters)}
{block("animations", clips)}
{block("volumes", volumes)}
{block("counters", counters)}
        lights_off: [{", ".join(str(g) for g in lights_off)}],
        events: [{event_list}],
{block("usables", usables)}
{block("breakables", breakables)}
{block("rules", rules)}
    ),
)
"""
OUT.write_text(level)
print(f"wrote {OUT}: {len(inst)} instances; slot centre z {slot_z:.2f} y {slot_y:.2f}")
