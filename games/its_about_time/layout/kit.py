"""The layout scripts' shared state and helpers: the level's lists (instances, clips, volumes,
usables, events, rules, breakables, counters, lights off) and the pieces the ruins are built of
(a kit piece placed, a wall coursed from blocks, a column, a block stretched to a box, a vault
with its gate and artifact, a lever). Metres, degrees; x east, y up, z south (north is -Z).
Every kit piece's origin is its bottom centre unless the kit says otherwise."""
import math

inst, clips, volumes, usables, events, rules = [], [], [], [], [], []
breakables, counters, lights_off, materials = [], [], [], []
grids, boxes = [], []
# Render areas (`render_areas` in the level): boxes naming the light groups sampled while the
# camera is inside. `area_group[0]` is the light group the emitters added now join (the area
# being laid out; None: no group, always sampled).
render_areas = []
area_group = [None]
EMISSIVE = ("torch_flame", "glyph_glow_")


def area(name, group, lo, hi, sees):
    """Starts laying out area `name`: emitters added from now on join light group `group`; the
    camera inside the box `lo`..`hi` (metres) samples the light groups `sees` only."""
    area_group[0] = group
    render_areas.append(f'(name: "{name}", min: {vec(*lo)}, max: {vec(*hi)}, '
                        f'light_groups: [{", ".join(str(g) for g in sees)}]),')

BLOCK = {"block_large": (2.4, 1.2, 1.2), "block_medium": (1.6, 0.8, 0.8), "block_small": (1.0, 0.5, 0.6)}


def fmt(v):
    return f"{v:g}" if isinstance(v, (int, float)) else str(v)


def vec(*v):
    return "(" + ", ".join(fmt(x) for x in v) + ")"


def add(model, x, y, z, name=None, rot=(0, 0, 0), scale=None, body="Static(shape: Box)",
        dynamic=False, material=None, light_group=None, extra=None):
    if light_group is None and model.startswith(EMISSIVE):
        light_group = area_group[0]
    s = f'(model: "{model}"'
    if name:
        s += f', name: "{name}"'
    t = f"translation: ({x:g}, {y:g}, {z:g})"
    if rot != (0, 0, 0):
        t += f", rotation_deg: ({rot[0]:g}, {rot[1]:g}, {rot[2]:g})"
    if scale:
        t += f", scale: ({scale[0]:g}, {scale[1]:g}, {scale[2]:g})"
    s += f", transform: ({t})"
    if material:
        s += f', material: Some("{material}")'
    if dynamic:
        s += ", dynamic: true"
    if light_group is not None:
        s += f", light_group: Some({light_group})"
    if extra:
        s += f", {extra}"
    if body:
        s += f", body: {body}"
    inst.append(s + "),")


def wall(x0, z0, x1, z1, courses, block="block_large", skip=None):
    """A wall of `courses` courses of blocks from (x0, z0) to (x1, z1) (axis-aligned), every other
    course set half a block along; `skip(s, y)` leaves out blocks whose centre is at distance s
    along the wall and height y (a doorway)."""
    bx, by, bz = BLOCK[block]
    length = abs(x1 - x0) + abs(z1 - z0)
    along_x = abs(x1 - x0) > abs(z1 - z0)
    n = max(1, round(length / bx))
    step = length / n
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
            scale = (scale_len, 1, 1) if abs(scale_len - 1) > 1e-3 else None
            if along_x:
                add(block, min(x0, x1) + mid, y, z0, scale=scale)
            else:
                add(block, x0, y, min(z0, z1) + mid, rot=(0, 90, 0), scale=scale)


def column(x, z, drums=3):
    for d in range(drums):
        add("column_drum", x, d, z)
    add("column_capital", x, drums, z)


def box_piece(x0, x1, y0, y1, z0, z1):
    """A large block stretched to fill the box [x0, x1] × [y0, y1] × [z0, z1]."""
    bx, by, bz = BLOCK["block_large"]
    add("block_large", (x0 + x1) / 2, y0, (z0 + z1) / 2,
        scale=((x1 - x0) / bx, (y1 - y0) / by, (z1 - z0) / bz))


def ashlar(x0, x1, y0, y1, z0, z1, course=1.2, length=2.4):
    """The box [x0, x1] × [y0, y1] × [z0, z1] built of coursed blocks (about `course` high and
    `length` long along the box's longer horizontal side, every other course set half a block
    along), each a large block scaled to its piece: a wall that reads as masonry, not a slab."""
    bx, by, bz = BLOCK["block_large"]
    along_x = (x1 - x0) >= (z1 - z0)
    a0, a1 = (x0, x1) if along_x else (z0, z1)
    n_courses = max(1, round((y1 - y0) / course))
    ch = (y1 - y0) / n_courses
    n = max(1, round((a1 - a0) / length))
    step = (a1 - a0) / n
    for c in range(n_courses):
        y = y0 + c * ch
        cuts = [a0 + k * step for k in range(n + 1)]
        if c % 2 and n > 1:
            cuts = [a0] + [a0 + (k + 0.5) * step for k in range(n)] + [a1]
        for a, b in zip(cuts, cuts[1:]):
            if b - a < 1e-3:
                continue
            if along_x:
                add("block_large", (a + b) / 2, y, (z0 + z1) / 2,
                    scale=((b - a) / bx, ch / by, (z1 - z0) / bz))
            else:
                add("block_large", (x0 + x1) / 2, y, (a + b) / 2, rot=(0, 90, 0),
                    scale=((b - a) / bx, ch / by, (x1 - x0) / bz))


def clip(name, target, prop, keys, interpolation="Linear"):
    """A clip of one track: `keys` are (seconds, value list), values relative to where the level
    places the target (a translation is added; a rotation turns it about its own origin)."""
    ks = ", ".join(f"(time_seconds: {t:g}, value: [{', '.join(fmt(v) for v in val)}])" for t, val in keys)
    clips.append(f'(name: "{name}", tracks: [(target: "{target}", property: {prop}, '
                 f'interpolation: {interpolation}, keys: [{ks}])]),')


def quat_x(deg):
    h = math.radians(deg) / 2
    return [round(math.sin(h), 6), 0, 0, round(math.cos(h), 6)]


def glyph_upright(glyph, x, y, z):
    """A glyph tile standing on a wall's south (+Z) face, its inlay glowing towards +Z."""
    add("glyph_tile", x, y, z, rot=(90, 0, 0), body=None)
    add(f"glyph_glow_{glyph}", x, y, z, rot=(90, 0, 0), body=None)


def vault(cx, z_front, name, artifact, model, material, width=2.6, depth=3.2, gate=True,
          scale=None, art_y=1.3, art_rot=(90, -90, 0), door_h=2.4, art_dx=0.0):
    """A small closed stone room north of `z_front` (its south face), centred on x = cx, with a
    doorway `width` wide and `door_h` high in the south wall closed by a carved gate (`<name>_gate`, raised by the
    clip `<name>_open`) unless `gate` is false (the caller closes it), and the artifact on a
    pedestal at the back (`art_dx` east of the middle): the instance `artifact` (a usable; its clip `<artifact>_taken` sinks
    it). Returns the doorway's x range."""
    T, H = 0.6, max(3.0, door_h + 0.6)
    x0, x1 = cx - width / 2 - 1.2, cx + width / 2 + 1.2       # inner faces
    z1 = z_front - T                                           # inner south face
    z0 = z1 - depth                                            # inner north face
    dx0, dx1 = cx - width / 2, cx + width / 2
    box_piece(x0 - T, dx0, 0, H, z1, z_front)                  # south wall, west of the door
    box_piece(dx1, x1 + T, 0, H, z1, z_front)                  # south wall, east of the door
    box_piece(dx0, dx1, H - 0.6, H, z1, z_front)               # over the door
    box_piece(x0 - T, x0, 0, H, z0 - T, z1)                    # west
    box_piece(x1, x1 + T, 0, H, z0 - T, z1)                    # east
    box_piece(x0, x1, 0, H, z0 - T, z0)                        # north
    box_piece(x0 - T - 0.2, x1 + T + 0.2, H, H + 0.4, z0 - T - 0.2, z_front + 0.2)  # roof
    add("torch", x0 + 0.5, 0, z0 + 0.5)
    add("torch_flame", x0 + 0.5, 1.5, z0 + 0.5, body=None)
    if gate:
        gz = z_front + 0.31
        add("carved_panel", cx, 0, gz, name=f"{name}_gate", scale=(width / 2, 1.25, 1),
            dynamic=True, body="Kinematic(shape: Box)")
        clip(f"{name}_open", f"{name}_gate", "Translation", [(0, [0, 0, 0]), (2, [0, 2.45, 0])])
    pz, ax = z0 + 1.0, cx + art_dx
    add("block_medium", ax, 0, pz, name=f"{name}_pedestal")
    add(model, ax, art_y, pz, name=artifact, rot=art_rot, scale=scale, material=material,
        dynamic=True, body="Kinematic(shape: Box)")
    clip(f"{artifact}_taken", artifact, "Translation", [(0, [0, 0, 0]), (1, [0, -2.8, 0])])
    return dx0, dx1


def artifact_rules(artifact, label):
    """The usable and the rule that take an artifact: counted, sunk out of sight, a chime."""
    events.append(artifact)
    usables.append(f'(instance: "{artifact}", prompt: "E  take the {label}", event: "{artifact}"),')
    rules.append(f'(name: "take_{artifact[len("artifact_"):]}", when: Event("{artifact}"), '
                 f'then: [Count(counter: "artifacts"), Play(clip: "{artifact}_taken"), Sound(sound: "artifact_chime")], once: true),')


def lever(x, z, name, prompt, y=0.0):
    """A lever (base + handle) standing at (x, y, z) whose handle swings 70° about its pivot
    when the clip `<name>_pull` plays; the base is the usable `name` sending the event `name`."""
    add("lever_base", x, y, z, name=name, body="Static(shape: Box)")
    add("lever_handle", x, y + 0.5, z, name=f"{name}_handle", rot=(-35, 0, 0),
        dynamic=True, body=None)
    clip(f"{name}_pull", f"{name}_handle", "Rotation", [(0, quat_x(0)), (0.6, quat_x(70))])
    events.append(name)
    usables.append(f'(instance: "{name}", prompt: "{prompt}", event: "{name}"),')
