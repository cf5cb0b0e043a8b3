//! The scratch folder the file-based targets write their input into: one per process and
//! thread, under `/dev/shm` when it exists (afl runs thousands of inputs a second), created on
//! first use with a fixed layout that the asset-path target resolves against.
//!
//! Layout: `root/` is the asset root (a level, a model and a texture inside it, a symlink
//! `root/escape` to the folder above the root and `root/models/loop` back to `root/models`),
//! `outside/secret.txt` lies beside it. Owns only this folder. Must not: write outside it.

use std::cell::OnceCell;
use std::path::{Path, PathBuf};

thread_local! {
    static FOLDER: OnceCell<PathBuf> = const { OnceCell::new() };
}

/// The scratch folder of this thread (made on first use).
pub fn folder() -> PathBuf {
    FOLDER.with(|cell| cell.get_or_init(make).clone())
}

/// The asset root inside [`folder`].
pub fn root() -> PathBuf {
    folder().join("root")
}

/// Writes `bytes` to `name` inside the asset root and returns the file's path.
pub fn write(name: &str, bytes: &[u8]) -> PathBuf {
    let path = root().join(name);
    if let Err(e) = std::fs::write(&path, bytes) {
        panic!("fuzz scratch: cannot write {}: {e}", path.display());
    }
    path
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
        std::fs::write(root.join("textures/t.png"), b"not really a png")?;
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

/// A one-triangle OBJ that uses material `m` from `fuzz.mtl`.
pub const FIXED_OBJ: &[u8] = b"mtllib fuzz.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nusemtl m\nf 1/1/1 2/2/1 3/3/1\n";

/// An MTL whose material `m` takes its colour from `fuzz_texture` (the texture target's file).
pub const TEXTURE_MTL: &[u8] = b"newmtl m\nKd 1 1 1\nmap_Kd fuzz_texture\n";

/// An MTL with one plain material `m` (for the OBJ target).
pub const PLAIN_MTL: &[u8] = b"newmtl m\nKd 0.5 0.5 0.5\n";
