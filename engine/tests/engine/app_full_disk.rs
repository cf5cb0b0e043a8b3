//! Atomic writes that fail half-way leave the previous file exactly as it was and no
//! temporary file behind, with an error naming the file and the stage that failed.
//!
//! A full disk is simulated with the file size limit (`RLIMIT_FSIZE`, with `SIGXFSZ` ignored
//! so the write returns `EFBIG` instead of killing the process): it works as root, where
//! `chmod` would not. The limit is per process, so this binary holds this one test only.
//! Also: the longest file name the file system takes still leaves room for the temporary one.

use crate::app_common;

use anyhow::Result;
use app_common::Scratch;
use candela::app::write_atomic;

#[test]
fn a_failed_write_keeps_the_old_file_and_leaves_no_temporary() -> Result<()> {
    let dir = Scratch::new("full_disk");
    let path = dir.join("progress.ron");
    write_atomic(&path, b"the old save")?;

    // SAFETY: setting a signal disposition and this process's own resource limit; no other
    // test runs in this binary.
    let old_limit = unsafe {
        libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
        let mut lim = std::mem::zeroed::<libc::rlimit>();
        assert_eq!(libc::getrlimit(libc::RLIMIT_FSIZE, &mut lim), 0);
        let small = libc::rlimit {
            rlim_cur: 4096,
            rlim_max: lim.rlim_max,
        };
        assert_eq!(libc::setrlimit(libc::RLIMIT_FSIZE, &small), 0);
        lim
    };
    let result = write_atomic(&path, &vec![b'x'; 256 * 1024]);
    // SAFETY: restoring the limit read above.
    unsafe {
        assert_eq!(libc::setrlimit(libc::RLIMIT_FSIZE, &old_limit), 0);
    }
    let e = result.expect_err("the 'disk' is full");
    assert_eq!(e.path, path);
    assert_eq!(e.stage, "write");
    assert_eq!(e.source.raw_os_error(), Some(libc::EFBIG));
    assert!(e.to_string().contains("progress.ron"), "{e}");
    assert_eq!(std::fs::read(&path)?, b"the old save");
    assert_eq!(Scratch::entries(dir.path()), ["progress.ron"]);

    // The longest name the file system takes: the temporary name must still fit beside it.
    let long = dir.join(&"s".repeat(255));
    write_atomic(&long, b"old")?;
    write_atomic(&long, b"new")?;
    assert_eq!(std::fs::read(&long)?, b"new");

    // And a write that can succeed does, replacing the content whole.
    write_atomic(&path, b"the new save")?;
    assert_eq!(std::fs::read(&path)?, b"the new save");
    assert_eq!(Scratch::entries(dir.path()).len(), 2);
    Ok(())
}
