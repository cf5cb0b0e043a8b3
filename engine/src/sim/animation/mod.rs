//! Animation: rigid keyframe clips (from glTF or authored in level files), skeletal skinning
//! and morph targets, and a player that turns time into poses.
//!
//! Flow: `gltf_anim` (with `gltf_anim_mesh`, `gltf_anim_clips`) loads an [`AnimatedModel`],
//! or `authored` reads RON clips → [`Clip`]s (`clip`) are sampled (`sample`) into a
//! [`Pose`] of local transforms and weights (`pose`), driven by an [`AnimationPlayer`]
//! (`player`: play, pause, loop, ping-pong, reverse, events, crossfades; for characters
//! `state_machine` picks the clip from how the body moves, `speed_blend` mixes walk and run by
//! speed, `action` plays what game code asks for, `character_anim` runs it per body)
//! → `pose` gives world matrices → `deform` morphs (`morph`) and skins (`skin`) vertices, as world-space positions
//! or as mesh-space `Vec<Vec3>` for the deforming-mesh refit in `accel::Upkeep::deform`.
//!
//! Runs on the main thread (game update). Must not: touch the renderer or BVHs; only
//! `entities` (clips that move level instances), `skinned_entities` (characters) and
//! `character_anim` (a character's body and its drawn model) touch the ECS.
//! Units: seconds (float64 clocks, float32 key times as glTF stores them), metres, radians; right-handed, +Y up.

mod action;
mod authored;
mod character_anim;
mod clip;
mod deform;
mod entities;
mod error;
mod gltf_anim;
mod gltf_anim_clips;
mod gltf_anim_mesh;
mod model;
mod morph;
mod player;
mod pose;
mod sample;
mod skin;
mod skinned_entities;
mod speed_blend;
mod state_machine;
mod upper_body;

pub use crate::assets::{AuthoredClip, AuthoredClipSet, AuthoredKey, AuthoredTrack};
pub use action::{ActionKind, ActionRequest, ActionSlot, YIELD_SPEED_MPS};
pub use character_anim::{
    CharacterAnimation, animate_characters, heading_direction, request_action, request_upper_body,
};
pub use clip::{Channel, Clip, ClipEvent, Interpolation, Property, check_clip};
pub use deform::{
    Deformed, PrimitiveRef, deform_mesh, deform_primitive, scene_primitives, world_positions,
};
pub use entities::EntityAnimations;
pub use error::{AnimError, AnimResult};
pub use gltf_anim::{load_animation, load_animation_bytes, load_animation_file};
pub use model::{AnimMesh, AnimPrimitive, AnimatedModel};
pub use morph::{MorphTarget, morph_normals, morph_positions, morph_tangents};
pub use player::{AnimationPlayer, FiredEvent, PlayMode, Playback};
pub use pose::{NodeRest, NodeTree, Pose};
pub use sample::{sample_channel, slerp};
pub use skin::{Influence, Skin, SkinnedVertices, joint_matrices, skin_vertices};
pub use skinned_entities::{SkinnedAnimator, deform_skinned, tick_skinned};
pub use speed_blend::{BlendPartner, SpeedBlend};
pub use state_machine::{
    AnimState, Contact, Locomotion, StateChange, StateCondition, StateMachine, StateMachineError,
    rate,
};
pub use upper_body::{
    UPPER_BODY_JOINT, UPPER_FADE_SECONDS, UpperBodySlot, UpperLayer, subtree_mask,
};
