//! Clicking a problem in the editor selects from the problem's typed item, never from its
//! message: with the message replaced or emptied, the same instance is selected.

use candela::editor::{Problem, check_references, instance_to_select};
use candela::level::ItemRef;

use crate::level_validate::with;

/// The instance selected for the only problem of the good level with one mistake, then for
/// the same problem with its message emptied and with another message.
fn selected(from: &str, to: &str) -> (ItemRef, Option<usize>) {
    let level = with(from, to);
    let problems = check_references(&level);
    assert_eq!(problems.len(), 1, "{problems:?}");
    let problem = &problems[0];
    let selected = instance_to_select(problem, &level);
    for message in [
        "",
        "rule \"done\" uses the instance \"lamp\" (instance 3, laser 0)",
    ] {
        let reworded = Problem {
            message: message.into(),
            ..problem.clone()
        };
        assert_eq!(
            instance_to_select(&reworded, &level),
            selected,
            "{message:?}"
        );
    }
    (problem.item, selected)
}

#[test]
fn the_selection_follows_the_typed_item_not_the_message() {
    // A problem of an instance selects it.
    assert_eq!(
        selected(r#"name: "crate", "#, r#"name: "crate", material: "gold", "#),
        (ItemRef::Instance(2), Some(2))
    );
    // A volume's, a laser's, an emitter's or a usable's problem selects its instance.
    assert_eq!(
        selected(
            r#"(name: "plate", instance: "plate")"#,
            r#"(name: "plate", instance: "crate")"#
        ),
        (ItemRef::Volume(0), Some(2))
    );
    assert_eq!(
        selected("direction: (1, 0, 0)", "direction: (0, 0, 0)"),
        (ItemRef::Laser(0), Some(4))
    );
    assert_eq!(
        selected(
            "sound: \"ding\", volume: 1)",
            "sound: \"ding\", volume: 20)"
        ),
        (ItemRef::Emitter(0), Some(3))
    );
    assert_eq!(
        selected(r#"prompt: "Press E""#, r#"prompt: """#),
        (ItemRef::Usable(0), Some(4))
    );
    // A rule sits on no instance: the selection (instances only) takes nothing, and the typed
    // item stays on the problem for the panel.
    assert_eq!(
        selected(r#"Occupied("plate")"#, r#"Occupied("plat")"#),
        (ItemRef::Rule(0), None)
    );
    // An item whose instance is missing selects nothing.
    assert_eq!(
        selected(
            r#"(name: "plate", instance: "plate")"#,
            r#"(name: "plate", instance: "gone")"#
        ),
        (ItemRef::Volume(0), None)
    );
}
