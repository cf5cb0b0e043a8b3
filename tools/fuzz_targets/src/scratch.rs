//! The scratch folder on disk: one per process and thread, under `/dev/shm` when it exists,
//! created once on first use with a fixed layout. Only two targets read it, and no target
//! writes to it per execution (every input stays in memory): `asset_path`, which resolves
//! paths against real symbolic links, and `level`, whose models, sounds and characters load
//! through the asset root on disk as in the game.
//!
//! Layout: `root/` is the asset root (a level, a model and a texture inside it, a symlink
//! `root/escape` to the folder above the root and `root/models/loop` back to `root/models`),
//! `outside/secret.txt` lies beside it. Owns only this folder. Must not: write outside it.

use std::cell::OnceCell;
use std::path::{Path, PathBuf};

use candela::assets::AssetRoot;

use crate::fixed::{FIXED_OBJ, NOT_A_PNG};

thread_local! {
    static FOLDER: OnceCell<PathBuf> = const { OnceCell::new() };
    static ROOT: OnceCell<AssetRoot> = const { OnceCell::new() };
}

/// The scratch folder of this thread (made on first use).
pub fn folder() -> PathBuf {
    FOLDER.with(|cell| cell.get_or_init(make).clone())
}

/// The asset root inside [`folder`].
pub fn root() -> PathBuf {
    folder().join("root")
}

/// The [`AssetRoot`] of [`root`] (opened once per thread).
pub fn asset_root() -> AssetRoot {
    ROOT.with(|cell| {
        cell.get_or_init(|| match AssetRoot::new(root()) {
            Ok(root) => root,
            Err(e) => panic!("fuzz scratch root: {e}"),
        })
        .clone()
    })
}

fn make() -> PathBuf {
    let base = if Path::new("/dev/shm").is_dir() {
        PathBuf::from("/dev/shm")
    } else {
        std::env::temp_dir()
    };
    let thread = format!("{:?}", std::thread::current().id())
        .chars()
        .filter(char::is_ascii_alphanumeric)
        .collect::<String>();
    let folder = base.join(format!("candela-fuzz-{}-{thread}", std::process::id()));
    let made = (|| -> std::io::Result<()> {
        let root = folder.join("root");
        std::fs::create_dir_all(root.join("models"))?;
        std::fs::create_dir_all(root.join("textures"))?;
        std::fs::create_dir_all(folder.join("outside"))?;
        std::fs::write(folder.join("outside/secret.txt"), b"outside the root")?;
        std::fs::write(root.join("models/box.obj"), FIXED_OBJ)?;
        std::fs::write(root.join("textures/t.png"), NOT_A_PNG)?;
        std::fs::write(root.join("level.ron"), b"()")?;
        #[cfg(unix)]
        {
            let link = |target: &str, at: PathBuf| -> std::io::Result<()> {
                if at.symlink_metadata().is_err() {
                    std::os::unix::fs::symlink(target, at)?;
                }
                Ok(())
            };
            link("..", root.join("escape"))?;
            link(".", root.join("models/loop"))?;
        }
        Ok(())
    })();
    if let Err(e) = made {
        panic!("fuzz scratch: cannot set up {}: {e}", folder.display());
    }
    folder
}
