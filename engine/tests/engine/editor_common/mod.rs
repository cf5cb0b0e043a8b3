//! Shared by the `editor_*` tests: the committed levels, a seeded random number generator,
//! random edits over every command kind, and a scratch folder removed when the test ends.

#![allow(dead_code)]

pub mod input;
pub mod mode_run;

use std::path::{Path, PathBuf};

use candela::assets::{
    BodyEntry, ConditionEntry, Detect, LaserEntry, Level, MaterialKind, ShapeEntry, TransformDesc,
};
use candela::editor::{
    Anchored, Document, Edit, InstanceField, LaserField, MaterialField, VolumeField,
};

pub fn assets() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../assets")
}

/// The first-person platform level as a document (comments included).
pub fn platform() -> anyhow::Result<Document> {
    Ok(Document::open(
        &assets().join("test_scenes/platform/first_person.ron"),
    )?)
}

/// The platform level with a laser on the switch, so that laser edits have one to edit.
pub fn platform_with_laser() -> anyhow::Result<Document> {
    let mut doc = platform()?;
    doc.level.gameplay.lasers.push(LaserEntry {
        instance: "switch".into(),
        origin: [0.0, 0.1, 0.1],
        direction: [0.0, 0.0, 1.0],
        max_reflections: 4,
        max_length: 30.0,
        beam: None,
    });
    Ok(doc)
}

/// Every committed level file that is a level on its own (Reflect's chamber files under
/// `assets/reflect/levels/` are parts of one world, loaded merged over their base file and
/// checked so by `games/reflect/tests/world.rs`).
pub fn committed_levels() -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![assets()];
    while let Some(dir) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "ron")
                && !path.parent().is_some_and(|p| p.ends_with("reflect/levels"))
                && std::fs::read_to_string(&path).is_ok_and(|t| t.contains("Level("))
            {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

/// Copies the folder `from` to `to`, recursively.
pub fn copy_dir(from: &Path, to: &Path) -> std::io::Result<()> {
    std::fs::create_dir_all(to)?;
    for entry in std::fs::read_dir(from)? {
        let entry = entry?;
        let target = to.join(entry.file_name());
        if entry.file_type()?.is_dir() {
            copy_dir(&entry.path(), &target)?;
        } else {
            std::fs::copy(entry.path(), &target)?;
        }
    }
    Ok(())
}

/// Reflect's world under `root` (a copy of `assets/`): the base file and the chambers' files,
/// in the order `assets/reflect/reflect.ron` lists them.
pub fn reflect_files(root: &Path) -> (PathBuf, Vec<PathBuf>) {
    let levels = root.join("reflect/levels");
    let parts = (1..=5)
        .map(|k| levels.join(format!("chamber_{k}.ron")))
        .collect();
    (levels.join("common.ron"), parts)
}

/// SplitMix64: the same sequence for the same seed.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(seed ^ 0x5851_f42d_4c95_7f2d)
    }

    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A number in `0..n` (`n` > 0).
    pub fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }

    /// A value in [-range, range] on a 1/64 grid (so RON writes it exactly and briefly).
    pub fn value(&mut self, range: f32) -> f32 {
        let steps = (range * 64.0) as usize;
        (self.below(2 * steps + 1) as f32 - steps as f32) / 64.0
    }

    pub fn vec3(&mut self, range: f32) -> [f32; 3] {
        [self.value(range), self.value(range), self.value(range)]
    }

    pub fn pick<'a, T>(&mut self, items: &'a [T]) -> Option<&'a T> {
        (!items.is_empty()).then(|| &items[self.below(items.len())])
    }

    pub fn coin(&mut self) -> bool {
        self.next() & 1 == 1
    }
}

fn names(level: &Level) -> (Vec<String>, Vec<String>, Vec<String>, Vec<String>) {
    let models = level
        .boxes
        .iter()
        .map(|b| b.name.clone())
        .chain(level.models.iter().map(|m| m.name.clone()))
        .collect();
    let materials = level.materials.iter().map(|m| m.name.clone()).collect();
    let instances = level
        .instances
        .iter()
        .filter_map(|i| i.name.clone())
        .collect();
    let volumes = level
        .gameplay
        .volumes
        .iter()
        .map(|v| v.name.clone())
        .collect();
    (models, materials, instances, volumes)
}

fn transform(rng: &mut Rng) -> TransformDesc {
    let scale = |rng: &mut Rng| (rng.below(32) + 1) as f32 / 8.0;
    TransformDesc {
        translation: rng.vec3(10.0),
        rotation_deg: rng.vec3(180.0),
        scale: [scale(rng), scale(rng), scale(rng)],
    }
}

fn body(rng: &mut Rng) -> Option<BodyEntry> {
    match rng.below(4) {
        0 => None,
        1 => Some(BodyEntry::Static {
            shape: ShapeEntry::Box,
        }),
        2 => Some(BodyEntry::Dynamic {
            shape: ShapeEntry::Sphere { radius: 0.25 },
            mass: (rng.below(40) + 1) as f32 / 4.0,
            ccd: rng.coin(),
        }),
        _ => Some(BodyEntry::Sensor {
            shape: ShapeEntry::Cuboid {
                half_extents: [0.5, rng.value(2.0).abs() + 0.125, 0.5],
            },
        }),
    }
}

fn condition(rng: &mut Rng, volumes: &[String], depth: u32) -> ConditionEntry {
    let volume = |rng: &mut Rng| rng.pick(volumes).cloned().unwrap_or_else(|| "none".into());
    match rng.below(if depth > 1 { 3 } else { 6 }) {
        0 => ConditionEntry::Occupied(volume(rng)),
        1 => ConditionEntry::Entered(volume(rng)),
        2 => ConditionEntry::Occupants {
            volume: volume(rng),
            at_least: rng.below(3) as u32 + 1,
        },
        3 => ConditionEntry::All(vec![
            condition(rng, volumes, depth + 1),
            condition(rng, volumes, depth + 1),
        ]),
        4 => ConditionEntry::Not(Box::new(condition(rng, volumes, depth + 1))),
        _ => ConditionEntry::Event("lever".into()),
    }
}

/// A random edit of any kind for `doc` (it may be one that fails: an index past the end, a
/// rewire of a volume the rule does not use).
pub fn random_edit(rng: &mut Rng, doc: &Document) -> Edit {
    let level = &doc.level;
    let (models, materials, instances, volumes) = names(level);
    let n = level.instances.len();
    let index = |rng: &mut Rng| rng.below(n + 1); // sometimes one past the end
    let some_name = |rng: &mut Rng, names: &[String]| rng.pick(names).cloned();
    let g = &level.gameplay;
    match rng.below(17) {
        0 | 1 => Edit::Instance {
            index: index(rng),
            field: InstanceField::Transform(transform(rng)),
        },
        2 => Edit::Instance {
            index: index(rng),
            field: InstanceField::Model(some_name(rng, &models).unwrap_or_default()),
        },
        3 => Edit::Instance {
            index: index(rng),
            field: InstanceField::Material(some_name(rng, &materials).filter(|_| rng.coin())),
        },
        4 => Edit::Instance {
            index: index(rng),
            field: InstanceField::LightGroup(rng.coin().then(|| rng.below(4) as u32)),
        },
        5 => Edit::Instance {
            index: index(rng),
            field: InstanceField::Body(body(rng)),
        },
        6 => Edit::Instance {
            index: index(rng),
            field: InstanceField::Dynamic(rng.coin()),
        },
        7 => Edit::Instance {
            index: index(rng),
            field: InstanceField::Name(rng.coin().then(|| format!("thing_{}", rng.below(5)))),
        },
        8 => {
            let mut entry = level
                .instances
                .get(rng.below(n))
                .cloned()
                .unwrap_or_else(|| candela::assets::InstanceEntry {
                    model: "floor".into(),
                    name: None,
                    transform: TransformDesc::default(),
                    material: None,
                    dynamic: false,
                    light_group: None,
                    waves: None,
                    body: None,
                });
            entry.transform = transform(rng);
            let comments = Anchored {
                before: vec![format!("// inserted {}", rng.below(100))],
                trailing: rng.coin().then(|| "// trailing".to_string()),
            };
            Edit::InsertInstance {
                index: index(rng),
                entry: Box::new(entry),
                comments: if rng.coin() {
                    comments
                } else {
                    Anchored::default()
                },
            }
        }
        9 => Edit::DuplicateInstance { index: index(rng) },
        10 | 11 => Edit::DeleteInstance { index: index(rng) },
        12 => {
            let field = match rng.below(9) {
                0 => MaterialField::Kind(
                    *rng.pick(&[
                        MaterialKind::Diffuse,
                        MaterialKind::Conductor,
                        MaterialKind::Dielectric,
                    ])
                    .expect("kinds"),
                ),
                1 => MaterialField::BaseColor(rng.vec3(1.0).map(f32::abs)),
                2 => MaterialField::Emission(rng.vec3(20.0).map(f32::abs)),
                3 => MaterialField::TwoSidedEmission(rng.coin()),
                4 => MaterialField::Roughness(rng.value(1.0).abs()),
                5 => MaterialField::Metallic(rng.value(1.0).abs()),
                6 => MaterialField::Ior(1.0 + rng.value(1.0).abs()),
                7 => MaterialField::AttenuationColor(rng.vec3(1.0).map(f32::abs)),
                _ => MaterialField::AttenuationDistance(rng.coin().then(|| rng.value(4.0).abs())),
            };
            Edit::Material {
                index: rng.below(level.materials.len() + 1),
                field,
            }
        }
        13 => {
            let field = match rng.below(5) {
                0 => LaserField::Origin(rng.vec3(1.0)),
                1 => LaserField::Direction(rng.vec3(1.0)),
                2 => LaserField::MaxReflections(rng.below(20) as u32),
                3 => LaserField::MaxLength(rng.value(100.0).abs() + 1.0),
                _ => LaserField::Instance(some_name(rng, &instances).unwrap_or_default()),
            };
            Edit::Laser {
                index: rng.below(g.lasers.len() + 1),
                field,
            }
        }
        14 => {
            let field = if rng.coin() {
                VolumeField::Instance(some_name(rng, &instances).unwrap_or_default())
            } else {
                let all = [Detect::Player, Detect::Bodies, Detect::Lasers];
                VolumeField::Detects(all.into_iter().filter(|_| rng.coin()).collect())
            };
            Edit::Volume {
                index: rng.below(g.volumes.len() + 1),
                field,
            }
        }
        15 => {
            let index = rng.below(g.rules.len() + 1);
            if rng.coin() {
                Edit::RuleCondition {
                    index,
                    when: condition(rng, &volumes, 0),
                }
            } else {
                Edit::RewireRule {
                    index,
                    from: some_name(rng, &volumes).unwrap_or_default(),
                    to: some_name(rng, &volumes).unwrap_or_default(),
                }
            }
        }
        _ => Edit::Batch(
            (0..rng.below(3) + 1)
                .map(|_| random_edit(rng, doc))
                .collect(),
        ),
    }
}

/// A fresh folder under the system temp folder, unique to this process and `tag`; removed
/// (made writable first) when dropped.
pub struct Scratch(PathBuf);

impl Scratch {
    pub fn new(tag: &str) -> Self {
        let dir = std::env::temp_dir().join(format!("candela_editor_{tag}_{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("create the scratch folder");
        Self(dir)
    }

    pub fn path(&self) -> &Path {
        &self.0
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        use std::os::unix::fs::PermissionsExt;
        let _ = std::fs::set_permissions(&self.0, std::fs::Permissions::from_mode(0o755));
        let _ = std::fs::remove_dir_all(&self.0);
    }
}
