"""The three puzzle areas after the sun gate: the court of weights (west), the rolling stone
(south-east) and the night shrine (north-west). Each adds its pieces, clips, volumes, usables
and rules to the lists in kit.py, and ends in a vault holding an artifact. Metres, degrees;
x east, y up, z south (north is -Z)."""
import math

from kit import (add, artifact_rules, breakables, clip, counters, events, glyph_upright, lever,
                 lights_off, rules, usables, vault, volumes, wall)

# Glyph numbers of the kit's inlays.
SUN, FRET, EYE, SERPENT = 0, 1, 2, 3
GLYPH_NAMES = {SUN: "sun", FRET: "fret", EYE: "eye", SERPENT: "serpent"}


def weights():
    """Four pressure plates in a row, each with its glyph; two pushable blocks. The vault
    opens while blocks weigh down the plates carved on its wall (sun and serpent) and the
    other two are empty. Block A starts in line with the sun plate; block B in line with the
    eye plate, so it must be pushed east first."""
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
                     f'then: [Sound(sound: "chime", at: "torch_{g}", volume: 0.2)]),')
        rules.append(f'(name: "torch_{g}_wrong", when: All([Event("torch_{g}"), {dark}, Not({at})]), '
                     f'then: [{all_off}, SetCounter(counter: "shrine", value: 0), Sound(sound: "door", at: "torch_{g}", volume: 0.5)]),')
        rules.append(f'(name: "torch_{g}_lit", when: All([Event("torch_{g}"), {dark}, {at}]), '
                     f'then: [Lights(group: {11 + glyph}, on: true), Count(counter: "shrine"), Sound(sound: "chime", at: "torch_{g}", volume: 0.5)]),')
    vault(-24.5, -22.5, "shrine", "artifact_night", "sun_disc", "silver")
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
