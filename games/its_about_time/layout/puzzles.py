"""The four puzzle areas after the sun gate: the water stair (north-east), the court of weights
(west), the rolling stone (south-east) and the night shrine (north-west). Each adds its pieces, clips, volumes, usables
and rules to the lists in kit.py, and ends in a vault holding an artifact. Metres, degrees;
x east, y up, z south (north is -Z)."""
import math

from kit import (add, area, artifact_rules, ashlar, boxes, breakables, clip, counters, events, glyph_upright,
                 grids, lever, lights_off, materials, rules, usables, vault, volumes, wall)

# Glyph numbers of the kit's inlays.
SUN, FRET, EYE, SERPENT = 0, 1, 2, 3
GLYPH_NAMES = {SUN: "sun", FRET: "fret", EYE: "eye", SERPENT: "serpent"}


def weights():
    """Four pressure plates in a row, each with its glyph; two pushable blocks. The vault
    opens while blocks weigh down the plates carved on its wall (sun and serpent) and the
    other two are empty. Block A starts in line with the sun plate; block B in line with the
    eye plate, so it must be pushed east first."""
    area("weights", 4, (-36, -1, -10), (-20, 15, 10), [1, 2, 4, 6, 11, 12, 13, 14])
    plates = [(-31.0, SUN), (-28.5, FRET), (-26.0, EYE), (-23.5, SERPENT)]
    pz = -2.0
    for x, glyph in plates:
        name = f"plate_{GLYPH_NAMES[glyph]}"
        add("pressure_plate_frame", x, 0, pz, body=None)
        add("pressure_plate", x, 0.02, pz, name=name, body=None)
        add(f"glyph_glow_{glyph}", x, 0.02, pz, body=None)
        add("sensor", x, 0.4, pz, name=f"{name}_zone",
            body="Sensor(shape: Cuboid(half_extents: (0.55, 0.35, 0.55)))")
        volumes.append(f'(name: "{name}", instance: "{name}_zone", detects: [Bodies]),')
    for name, x in [("weight_a", -31.0), ("weight_b", -26.0)]:
        add("push_block", x, 0.0, 2.5, name=name, dynamic=True,
            body="Dynamic(shape: Box, mass: 60)")
    # The vault north of the plates; the pattern carved beside its gate.
    vault(-27.25, -6.0, "weights", "artifact_weights", "boulder", "jade", scale=(0.28, 0.28, 0.28),
          art_y=1.05, art_rot=(0, 0, 0))
    glyph_upright(SUN, -30.2, 1.3, -5.94)
    glyph_upright(SERPENT, -24.3, 1.3, -5.94)
    # A low coursed wall closing the court to the west and south-west.
    wall(-34.5, -6.0, -34.5, 6.0, 1, block="block_medium")
    artifact_rules("artifact_weights", "Balance Stone")
    rules.append('(name: "weights_open", when: All([Occupied("plate_sun"), Occupied("plate_serpent"), '
                 'Not(Occupied("plate_fret")), Not(Occupied("plate_eye"))]), '
                 'then: [Play(clip: "weights_open"), Sound(sound: "stone_scrape", at: "weights_gate")], once: true),')


def rolling_stone():
    """A ramp rising south from z = 19 to 2.4 m at z = 27, a boulder on it held by a stone
    chock; the lever beside the ramp's foot sinks the chock, the boulder rolls north
    and breaks the brittle wall closing the vault (`impact_speed` 3 m/s)."""
    area("rolling_stone", 5, (10, -1, 8), (29, 15, 29), [1, 2, 4, 5, 6])
    cx = 19.0
    theta = math.atan2(2.4, 8.0)
    t, length, zc = 0.4, 9.0, 23.0
    y0 = 1.2 - t / math.cos(theta)
    add("block_large", cx, round(y0, 4), zc, rot=(-round(math.degrees(theta), 4), 0, 0),
        scale=(4.0 / 2.4, t / 1.2, round(length / 1.2, 4)))
    # The boulder rests against the chock on the slope.
    surface = lambda z: 1.2 + (z - zc) * math.tan(theta)
    bz = 25.6
    nx, ny = -math.sin(theta), math.cos(theta)
    add("boulder", cx, round(surface(bz) + 0.9 * ny, 4), round(bz + 0.9 * nx, 4), name="boulder_stone",
        dynamic=True, body="Dynamic(shape: Sphere(radius: 0.9), mass: 400, ccd: true)")
    cz = 24.2
    add("block_medium", cx, round(surface(cz) - 0.35, 4), cz, name="boulder_chock",
        dynamic=True, body="Kinematic(shape: Box)")
    # The chock sinks into the ramp (a kinematic body sliding sideways along the boulder
    # flings it off the ramp).
    clip("boulder_chock_aside", "boulder_chock", "Translation",
         [(0, [0, 0, 0]), (0.6, [0, -0.9, 0])])
    lever(22.6, 20.0, "boulder_lever", "E  pull the lever")
    # The vault north of the ramp: its doorway is the brittle wall.
    zf = 15.0
    d0, d1 = vault(cx, zf, "stone", "artifact_stone", "boulder", "obsidian", width=4.0, depth=4.0,
                   gate=False, scale=(0.3, 0.3, 0.3), art_y=1.07, art_rot=(0, 0, 0), door_h=3.0, art_dx=2.2)
    pieces = [f"brittle_wall_piece_{i}" for i in range(9)]
    for p in pieces:
        add(p, cx, 0, zf - 0.3, name=f"stone_wall_{p[-1]}", dynamic=True, body="Static(shape: ConvexHull)")
    names = ", ".join(f'"stone_wall_{p[-1]}"' for p in pieces)
    breakables.append(f'(name: "stone_wall", pieces: [{names}], impact_speed: Some(3.0), piece_mass: 30),')
    rules.append('(name: "boulder_released", when: Event("boulder_lever"), then: [Play(clip: "boulder_lever_pull"), '
                 'Play(clip: "boulder_chock_aside"), Sound(sound: "stone_scrape", at: "boulder_chock")], once: true),')
    artifact_rules("artifact_stone", "Thunder Stone")


def night_shrine():
    """Four torches in a row before a vault, each with its glyph on the ground; the vault's
    wall shows the order (eye, sun, serpent, fret, left to right). A torch takes only after
    dark (the sun 6° below the horizon); lit in order, the vault opens; a wrong torch puts them
    all out."""
    area("night_shrine", 6, (-34, -1, -28), (-13, 15, -3), [1, 2, 4, 6, 11, 12, 13, 14])
    order = [EYE, SUN, SERPENT, FRET]
    torches = [(-29.5, SUN), (-26.5, FRET), (-22.5, EYE), (-19.5, SERPENT)]
    counters.append('(name: "shrine"),')
    zt = -18.5
    groups = []
    for x, glyph in torches:
        g = GLYPH_NAMES[glyph]
        group = 11 + glyph
        groups.append(group)
        lights_off.append(group)
        add("torch", x, 0, zt, name=f"torch_{g}")
        add("torch_flame", x, 1.5, zt, name=f"torch_{g}_flame", body=None, light_group=group)
        add("glyph_tile", x, 0.0, zt + 1.3, body=None)
        add(f"glyph_glow_{glyph}", x, 0.0, zt + 1.3, body=None)
        events.append(f"torch_{g}")
        usables.append(f'(instance: "torch_{g}", prompt: "E  light the torch", event: "torch_{g}"),')
    all_off = ", ".join(f"Lights(group: {g}, on: false)" for g in groups)
    dark, day = "SunElevation(at_most: Some(-6))", "SunElevation(at_least: Some(-6))"
    for x, glyph in torches:
        g = GLYPH_NAMES[glyph]
        i = order.index(glyph)
        at = f'Counter(counter: "shrine", at_least: {i}, at_most: {i})'
        rules.append(f'(name: "torch_{g}_daylight", when: All([Event("torch_{g}"), {day}]), '
                     f'then: [Sound(sound: "torch_douse", at: "torch_{g}", volume: 0.25)]),')
        rules.append(f'(name: "torch_{g}_wrong", when: All([Event("torch_{g}"), {dark}, Not({at})]), '
                     f'then: [{all_off}, SetCounter(counter: "shrine", value: 0), Sound(sound: "torch_douse", at: "torch_{g}", volume: 0.7)]),')
        rules.append(f'(name: "torch_{g}_lit", when: All([Event("torch_{g}"), {dark}, {at}]), '
                     f'then: [Lights(group: {11 + glyph}, on: true), Count(counter: "shrine"), Sound(sound: "torch_ignite", at: "torch_{g}", volume: 0.7)]),')
    vault(-24.5, -22.5, "shrine", "artifact_night", "sun_disc", "silver", art_rot=(0, 0, 0))
    # A second sun altar by the shrine, to bring the night (the game turns time at any usable
    # sending "sun_altar"); a rule that holds while it is dark, for the HUD and the bot.
    add("sun_altar", -19, 0, -12, name="shrine_altar")
    usables.append('(instance: "shrine_altar", prompt: "Hold Q or R to turn time", event: "sun_altar"),')
    rules.append(f'(name: "night_falls", when: {dark}, then: []),')
    for k, glyph in enumerate(order):
        x = [-30.0, -28.4, -20.6, -19.0][k]
        glyph_upright(glyph, x, 1.2, -22.44)
    rules.append('(name: "shrine_open", when: Counter(counter: "shrine", at_least: 4), '
                 'then: [Play(clip: "shrine_open"), Sound(sound: "stone_scrape", at: "shrine_gate")], once: true),')
    artifact_rules("artifact_night", "Moon Mirror")


def water_stair():
    """A walled pool (8 × 8 m inside, walls 3.6 m) whose water stands 2.4 m deep at the start,
    its doorway closed by a sluice gate. The lever by the door drains it (the gate rises once
    the water is down); inside, the lever beside the reed float fills it again, and the float
    rides the water up to the terrace along the north wall (2.7 m: too high to climb), where the
    Rain Jar stands; the lever on the terrace drains it to come down, and one inside by the
    door drains it for anyone shut in. The counter `pool` holds 1 while the pool is drained.
    The water ripples where the explorer wades."""
    area("water_stair", 3, (12, -1, -24), (29, 15, -7), [1, 2, 3, 6, 14])
    x0, x1, z0, z1 = 17.0, 25.0, -22.0, -14.0          # inner faces west / east / north / south
    T, H = 0.6, 3.6
    cx = (x0 + x1) / 2
    door0, door1, door_h = cx - 0.8, cx + 0.8, 2.4
    ashlar(x0 - T, x0, 0, H, z0 - T, z1 + T)           # west
    ashlar(x1, x1 + T, 0, H, z0 - T, z1 + T)           # east
    ashlar(x0, x1, 0, H, z0 - T, z0)                   # north
    ashlar(x0, door0, 0, H, z1, z1 + T)                # south, west of the door
    ashlar(door1, x1, 0, H, z1, z1 + T)                # south, east of the door
    ashlar(door0, door1, door_h, H, z1, z1 + T)        # over the door
    # The terrace along the north wall, its face at z = -18.6.
    top, face = 2.7, -18.6
    ashlar(x0, x1, 0, top, z0, face)
    # The water: a simulated grid over the open part of the pool (18k triangles, as in the
    # paper), its rest surface 2.6 m up at the start.
    hi, drop = 2.6, 2.4
    size_x, size_z = x1 - x0, z1 - face
    grids.append(f'(name: "pool_water", size: ({size_x:g}, {size_z:g}), divisions: (112, 80), material: "water"),')
    add("pool_water", cx, hi, (z1 + face) / 2, name="pool", dynamic=True, body=None,
        extra='waves: Some((amplitude: 0, wavelength: 2.5, speed: 0.4, '
              'simulate: Some((wave_speed: 1.2, damping: 0.5, push: 0.12, start_at_rest: true))))')
    materials.append('(name: "water", kind: Dielectric, ior: 1.33, attenuation_color: (0.5, 0.78, 0.7), '
                     'attenuation_distance: 3.5),')
    materials.append('(name: "reed", kind: Diffuse, base_color: (0.45, 0.35, 0.19)),')
    # The reed float: its top level with the terrace while the pool is full.
    ft = 0.28
    boxes.append(f'(name: "reed_float", size: (2.2, {ft:g}, 2.2), material: "reed"),')
    fz = face + 0.1 + 1.1
    add("reed_float", cx, top - ft / 2, fz, name="pool_float", dynamic=True, body="Kinematic(shape: Box)")
    # The sluice gate in the doorway.
    add("carved_panel", cx, 0, z1 + T / 2, name="pool_sluice", scale=(0.8, 1.25, 1),
        dynamic=True, body="Kinematic(shape: Box)")
    # Draining: 1.5 s of groaning, 4 s down, then the sluice rises; filling (the same clips
    # reversed): the sluice shuts, 2 s still (time to step onto the float), 4 s up.
    down = [(0, [0, 0, 0]), (1.5, [0, 0, 0]), (5.5, [0, -drop, 0]), (7.5, [0, -drop, 0])]
    clip("pool_drain", "pool", "Translation", down)
    clip("pool_float_drain", "pool_float", "Translation", down)
    clip("pool_sluice_open", "pool_sluice", "Translation",
         [(0, [0, 0, 0]), (5.5, [0, 0, 0]), (7.5, [0, 2.45, 0])])
    # Levers: three open the sluice (by the door outside, by the door inside, so no one is
    # ever shut in, and on the terrace); the one beside the float shuts it. Rules fire on the
    # lever's event and the counter `pool` (1 while drained); a lever toggling one counter
    # would undo itself in the same step, as the rules run until nothing changes.
    drains = [("sluice", cx + 2.2, z1 + T + 1.0, 0.0), ("door", cx - 2.0, z1 - 1.0, 0.0),
              ("terrace", cx + 2.6, face - 1.8, top)]
    for name, lx, lz, ly in drains:
        lever(lx, lz, f"{name}_lever", "E  open the sluice: the pool drains", y=ly)
    lever(cx + 2.2, fz, "fill_lever", "E  shut the sluice: the pool fills")
    names = [n for n, *_ in drains] + ["fill"]
    counters.append('(name: "pool"),')
    low, full = 'Counter(counter: "pool", at_least: 1)', 'Counter(counter: "pool", at_most: 0)'
    pulls = lambda verb: ", ".join(f'{verb}(clip: "{n}_lever_pull")' for n in names)
    drain = ('Play(clip: "pool_drain"), Play(clip: "pool_float_drain"), Play(clip: "pool_sluice_open"), '
             f'{pulls("Play")}, SetCounter(counter: "pool", value: 1), Sound(sound: "sluice", at: "pool_sluice")')
    fill = ('Reverse(clip: "pool_drain"), Reverse(clip: "pool_float_drain"), Reverse(clip: "pool_sluice_open"), '
            f'{pulls("Reverse")}, SetCounter(counter: "pool", value: 0), Sound(sound: "sluice", at: "pool_sluice")')
    for name, *_ in drains:
        rules.append(f'(name: "pool_drains_{name}", when: All([Event("{name}_lever"), {full}]), then: [{drain}]),')
    rules.append(f'(name: "pool_fills", when: All([Event("fill_lever"), {low}]), then: [{fill}]),')
    # The Rain Jar on its pedestal at the back of the terrace, more than a reach (1.8 m) from
    # the pool floor and from outside the north wall; the glyphs of sun and serpent beside it.
    az = -20.6
    add("block_medium", cx, top, az, name="water_pedestal")
    add("column_drum", cx, top + 0.8, az, name="artifact_water", scale=(0.32, 0.42, 0.32),
        material="turquoise", dynamic=True, body="Kinematic(shape: Box)")
    materials.append('(name: "turquoise", kind: MetalRough, base_color: (0.08, 0.5, 0.52), roughness: 0.2),')
    clip("artifact_water_taken", "artifact_water", "Translation", [(0, [0, 0, 0]), (1, [0, -2.8, 0])])
    add("torch", x0 + 0.6, top, z0 + 0.6)
    add("torch_flame", x0 + 0.6, top + 1.5, z0 + 0.6, body=None)
    add("torch", x1 - 0.6, top, z0 + 0.6)
    add("torch_flame", x1 - 0.6, top + 1.5, z0 + 0.6, body=None)
    artifact_rules("artifact_water", "Rain Jar")
