//! The editable fields of level items: each enum names one field of an instance, a level
//! material, a laser or a trigger volume together with a value for it, and swapping a value
//! in returns the one it replaced (which is how an edit's inverse is made).
//!
//! Main thread. Must not: know about the history or the world.

use crate::assets::{
    BodyEntry, Detect, InstanceEntry, LaserEntry, LevelMaterial, MaterialKind, TransformDesc,
    VolumeEntry,
};

/// A field of an instance, with its new value.
#[derive(Clone, Debug, PartialEq)]
pub enum InstanceField {
    Transform(TransformDesc),
    Model(String),
    Name(Option<String>),
    /// A level material replacing the model's, or the model's own (`None`).
    Material(Option<String>),
    LightGroup(Option<u32>),
    Body(Option<BodyEntry>),
    Dynamic(bool),
}

/// A field of a level material, with its new value (colours linear RGB; emission
/// W·sr⁻¹·m⁻²; attenuation distance metres).
#[derive(Clone, Debug, PartialEq)]
pub enum MaterialField {
    Kind(MaterialKind),
    BaseColor([f32; 3]),
    Emission([f32; 3]),
    TwoSidedEmission(bool),
    Roughness(f32),
    Metallic(f32),
    Ior(f32),
    AttenuationColor([f32; 3]),
    AttenuationDistance(Option<f32>),
}

/// A field of a laser, with its new value (origin metres and direction in the instance's
/// model space; length metres).
#[derive(Clone, Debug, PartialEq)]
pub enum LaserField {
    Instance(String),
    Origin([f32; 3]),
    Direction([f32; 3]),
    MaxReflections(u32),
    MaxLength(f32),
}

/// A field of a trigger volume, with its new value.
#[derive(Clone, Debug, PartialEq)]
pub enum VolumeField {
    /// The sensor instance whose shape the volume is.
    Instance(String),
    Detects(Vec<Detect>),
}

impl InstanceField {
    /// The field's name, for descriptions and merge keys.
    pub fn name(&self) -> &'static str {
        match self {
            InstanceField::Transform(_) => "transform",
            InstanceField::Model(_) => "model",
            InstanceField::Name(_) => "name",
            InstanceField::Material(_) => "material",
            InstanceField::LightGroup(_) => "light group",
            InstanceField::Body(_) => "body",
            InstanceField::Dynamic(_) => "dynamic flag",
        }
    }

    /// Puts this value into `e` and returns the one it replaced.
    pub(super) fn swap(self, e: &mut InstanceEntry) -> InstanceField {
        use std::mem::replace;
        match self {
            Self::Transform(v) => Self::Transform(replace(&mut e.transform, v)),
            Self::Model(v) => Self::Model(replace(&mut e.model, v)),
            Self::Name(v) => Self::Name(replace(&mut e.name, v)),
            Self::Material(v) => Self::Material(replace(&mut e.material, v)),
            Self::LightGroup(v) => Self::LightGroup(replace(&mut e.light_group, v)),
            Self::Body(v) => Self::Body(replace(&mut e.body, v)),
            Self::Dynamic(v) => Self::Dynamic(replace(&mut e.dynamic, v)),
        }
    }
}

impl MaterialField {
    /// The field's name, for descriptions and merge keys.
    pub fn name(&self) -> &'static str {
        match self {
            MaterialField::Kind(_) => "kind",
            MaterialField::BaseColor(_) => "base colour",
            MaterialField::Emission(_) => "emission",
            MaterialField::TwoSidedEmission(_) => "two-sided emission",
            MaterialField::Roughness(_) => "roughness",
            MaterialField::Metallic(_) => "metallic",
            MaterialField::Ior(_) => "IOR",
            MaterialField::AttenuationColor(_) => "attenuation colour",
            MaterialField::AttenuationDistance(_) => "attenuation distance",
        }
    }

    /// Puts this value into `m` and returns the one it replaced.
    pub(super) fn swap(self, m: &mut LevelMaterial) -> MaterialField {
        use std::mem::replace;
        match self {
            Self::Kind(v) => Self::Kind(replace(&mut m.kind, v)),
            Self::BaseColor(v) => Self::BaseColor(replace(&mut m.base_color, v)),
            Self::Emission(v) => Self::Emission(replace(&mut m.emission, v)),
            Self::TwoSidedEmission(v) => {
                Self::TwoSidedEmission(replace(&mut m.two_sided_emission, v))
            }
            Self::Roughness(v) => Self::Roughness(replace(&mut m.roughness, v)),
            Self::Metallic(v) => Self::Metallic(replace(&mut m.metallic, v)),
            Self::Ior(v) => Self::Ior(replace(&mut m.ior, v)),
            Self::AttenuationColor(v) => {
                Self::AttenuationColor(replace(&mut m.attenuation_color, v))
            }
            Self::AttenuationDistance(v) => {
                Self::AttenuationDistance(replace(&mut m.attenuation_distance, v))
            }
        }
    }
}

impl LaserField {
    /// Puts this value into `l` and returns the one it replaced.
    pub(super) fn swap(self, l: &mut LaserEntry) -> LaserField {
        use std::mem::replace;
        match self {
            Self::Instance(v) => Self::Instance(replace(&mut l.instance, v)),
            Self::Origin(v) => Self::Origin(replace(&mut l.origin, v)),
            Self::Direction(v) => Self::Direction(replace(&mut l.direction, v)),
            Self::MaxReflections(v) => Self::MaxReflections(replace(&mut l.max_reflections, v)),
            Self::MaxLength(v) => Self::MaxLength(replace(&mut l.max_length, v)),
        }
    }

    /// The field's name, for descriptions and merge keys.
    pub fn name(&self) -> &'static str {
        match self {
            LaserField::Instance(_) => "instance",
            LaserField::Origin(_) => "origin",
            LaserField::Direction(_) => "direction",
            LaserField::MaxReflections(_) => "max reflections",
            LaserField::MaxLength(_) => "max length",
        }
    }
}

impl VolumeField {
    /// Puts this value into `v` and returns the one it replaced.
    pub(super) fn swap(self, v: &mut VolumeEntry) -> VolumeField {
        use std::mem::replace;
        match self {
            Self::Instance(n) => Self::Instance(replace(&mut v.instance, n)),
            Self::Detects(d) => Self::Detects(replace(&mut v.detects, d)),
        }
    }

    /// The field's name, for descriptions and merge keys.
    pub fn name(&self) -> &'static str {
        match self {
            VolumeField::Instance(_) => "instance",
            VolumeField::Detects(_) => "detects",
        }
    }
}
