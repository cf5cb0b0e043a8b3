//! Broken versions of the ruins give a clear error naming the file and the item, never a
//! panic: an artifact whose event no rule waits for (wired to nothing), a lever wired to
//! nothing, an explorer missing, a rule that counts an artifact no counter holds, and the night
//! shrine's torches waiting for a sun below −90°.

use std::path::{Path, PathBuf};

use its_about_time::world::RuinsWorld;

fn ruins() -> anyhow::Result<String> {
    Ok(std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/its_about_time/ruins.ron"),
    )?)
}

/// Copies the folder `from` into `to` (files and subfolders).
fn copy_dir(from: &Path, to: &Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(to)?;
    for entry in std::fs::read_dir(from)? {
        let entry = entry?;
        let target = to.join(entry.file_name());
        if entry.file_type()?.is_dir() {
            copy_dir(&entry.path(), &target)?;
        } else {
            std::fs::copy(entry.path(), target)?;
        }
    }
    Ok(())
}

/// Writes `text` as a level under a temporary asset root holding copies of the kit and the
/// hero (the asset root refuses links out of it), and tries to load it; returns the error.
fn load_error(name: &str, text: &str) -> anyhow::Result<String> {
    let root = std::env::temp_dir().join(format!("iat_bad_{name}_{}", std::process::id()));
    let assets = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets");
    let _ = std::fs::remove_dir_all(&root);
    std::fs::create_dir_all(root.join("its_about_time"))?;
    for folder in ["common/hero", "its_about_time/kit", "its_about_time/sounds"] {
        copy_dir(&assets.join(folder), &root.join(folder))?;
    }
    let level: PathBuf = root.join("its_about_time/ruins.ron");
    std::fs::write(&level, text)?;
    let result = RuinsWorld::open(Some(&level));
    let _ = std::fs::remove_dir_all(&root);
    match result {
        Ok(_) => anyhow::bail!("{name}: the broken level loaded"),
        Err(e) => Ok(format!("{e:#}")),
    }
}

#[test]
fn an_artifact_wired_to_nothing_is_named() -> anyhow::Result<()> {
    let text = ruins()?.replace(
        "when: Event(\"artifact_sun\")",
        "when: Event(\"sun_altar\")",
    );
    let err = load_error("wired", &text)?;
    assert!(
        err.contains("ruins.ron") && err.contains("artifact_sun"),
        "{err}"
    );
    Ok(())
}

#[test]
fn ruins_without_an_explorer_are_refused() -> anyhow::Result<()> {
    let text = ruins()?;
    let start = text
        .find("    characters: [(")
        .ok_or_else(|| anyhow::anyhow!("no characters"))?;
    let end = text[start..]
        .find("    )],\n")
        .ok_or_else(|| anyhow::anyhow!("no end"))?
        + start;
    let text = format!("{}{}", &text[..start], &text[end + "    )],\n".len()..]);
    let err = load_error("explorer", &text)?;
    assert!(
        err.contains("ruins.ron") && err.contains("character"),
        "{err}"
    );
    Ok(())
}

#[test]
fn a_count_of_an_unknown_counter_is_named() -> anyhow::Result<()> {
    let text = ruins()?.replace(
        "then: [Count(counter: \"artifacts\")",
        "then: [Count(counter: \"relics\")",
    );
    let err = load_error("counter", &text)?;
    assert!(err.contains("ruins.ron") && err.contains("relics"), "{err}");
    Ok(())
}

#[test]
fn a_lever_wired_to_nothing_is_named() -> anyhow::Result<()> {
    let text = ruins()?.replace(
        "when: Event(\"boulder_lever\")",
        "when: Fired(\"take_sun\")",
    );
    assert_ne!(text, ruins()?, "the ruins have no boulder lever rule");
    let err = load_error("lever", &text)?;
    assert!(
        err.contains("ruins.ron") && err.contains("boulder_lever"),
        "{err}"
    );
    Ok(())
}

#[test]
fn a_sun_below_the_nadir_is_named() -> anyhow::Result<()> {
    let text = ruins()?.replace(
        "Event(\"torch_eye\"), SunElevation(at_most: Some(-6))",
        "Event(\"torch_eye\"), SunElevation(at_most: Some(-100))",
    );
    assert_ne!(text, ruins()?, "the ruins have no eye torch rule");
    let err = load_error("nadir", &text)?;
    assert!(
        err.contains("ruins.ron") && err.contains("torch_eye") && err.contains("-90 to 90"),
        "{err}"
    );
    Ok(())
}
