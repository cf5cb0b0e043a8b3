//! The recording file's bytes are the layout `app/replay/format.rs` documents, its checksum is
//! FNV-1a 64 (checked against the published test vector), and the per-step fixed point of
//! axes and motions rounds and saturates as `action_frame.rs` says.

use anyhow::Result;
use candela::app::{
    ActionDef, ActionFrame, ActionKind, ActionSet, Binding, FORMAT_VERSION, KeyCode, RecordedLook,
    Recorder, Recording, fnv1a64, quantise_axis, quantise_motion,
};

#[test]
fn the_file_layout_is_the_documented_one() -> Result<()> {
    let set = ActionSet::new(vec![
        ActionDef {
            name: "go".into(),
            kind: ActionKind::Button,
            defaults: vec![Binding::Key(KeyCode::KeyG)],
        },
        ActionDef {
            name: "turn".into(),
            kind: ActionKind::Motion,
            defaults: vec![Binding::MouseX],
        },
    ])?;
    let mut rec = Recorder::new("g", "l", 0x1122_3344_5566_7788, 50.0, &set);
    rec.set_look(RecordedLook {
        mouse_sensitivity: 1.5,
        invert_y: true,
    });
    let frame = ActionFrame {
        held: 1,
        pressed: 1,
        values: vec![0, -256],
    };
    rec.push(frame.clone())?;
    rec.push(frame)?;
    let bytes = rec.recording().encode();
    let mut expected: Vec<u8> = Vec::new();
    expected.extend(b"CDLAREC\0");
    expected.extend(FORMAT_VERSION.to_le_bytes());
    expected.extend(1u32.to_le_bytes());
    expected.extend(b"g");
    expected.extend(1u32.to_le_bytes());
    expected.extend(b"l");
    expected.extend(0x1122_3344_5566_7788u64.to_le_bytes());
    expected.extend(50.0f64.to_le_bytes());
    expected.extend(1.5f32.to_le_bytes()); // look sensitivity
    expected.push(1); // invert Y
    expected.extend(2u64.to_le_bytes()); // steps
    expected.extend(2u16.to_le_bytes()); // actions
    expected.push(0);
    expected.extend(2u32.to_le_bytes());
    expected.extend(b"go");
    expected.push(2);
    expected.extend(4u32.to_le_bytes());
    expected.extend(b"turn");
    expected.extend(2u32.to_le_bytes()); // one run of two steps
    expected.extend(1u64.to_le_bytes());
    expected.extend(1u64.to_le_bytes());
    expected.extend((-256i32).to_le_bytes()); // the motion only: buttons carry no value
    let sum = fnv1a64(&expected);
    expected.extend(sum.to_le_bytes());
    assert_eq!(bytes, expected);
    assert_eq!(FORMAT_VERSION, 2);

    // The same file in version 1 (no look fields) reads with the default look, same steps.
    let mut v1: Vec<u8> = Vec::new();
    v1.extend(&expected[..8]);
    v1.extend(1u32.to_le_bytes());
    let step_rate_end = 12 + 5 + 5 + 8 + 8;
    v1.extend(&expected[12..step_rate_end]);
    v1.extend(&expected[step_rate_end + 5..expected.len() - 8]);
    let sum = fnv1a64(&v1);
    v1.extend(sum.to_le_bytes());
    let old = Recording::decode(std::path::Path::new("v1.replay"), &v1)?;
    assert_eq!(old.header.look, RecordedLook::default());
    assert_eq!(old.runs, rec.recording().runs);
    let new = Recording::decode(std::path::Path::new("v2.replay"), &bytes)?;
    assert_eq!(new.header.look.mouse_sensitivity, 1.5);
    assert!(new.header.look.invert_y);
    // FNV-1a 64 of "a" (the published test vector).
    assert_eq!(fnv1a64(b"a"), 0xaf63_dc4c_8601_ec8c);
    Ok(())
}

#[test]
fn fixed_point_is_exact_rounded_and_saturating() {
    assert_eq!(quantise_axis(1.0), 32767);
    assert_eq!(quantise_axis(-1.0), -32767);
    assert_eq!(quantise_axis(7.0), 32767);
    assert_eq!(quantise_axis(f32::NAN), 0);
    assert_eq!(quantise_axis(0.5), 16384); // 16383.5 rounds away from zero
    assert_eq!(quantise_motion(1.5), 384);
    assert_eq!(quantise_motion(-0.001), 0);
    assert_eq!(quantise_motion(f32::NAN), 0);
    assert_eq!(quantise_motion(1e30), i32::MAX);
    assert_eq!(quantise_motion(-1e30), i32::MIN);
}
