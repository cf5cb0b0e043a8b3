//! The afl entry point: `CANDELA_FUZZ_TARGET=<name> cargo afl fuzz … -- candela_fuzz` runs one
//! target of `fuzz_targets` per input afl hands it; `candela_fuzz --write-seeds <name> DIR`
//! writes that target's seeds into DIR (afl's `-i`). See docs/RELIABILITY.md.

use fuzz_targets::{Target, run, seeds::seeds};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("--write-seeds") {
        std::process::exit(write_seeds(&args[1..]));
    }
    let name = std::env::var("CANDELA_FUZZ_TARGET").unwrap_or_default();
    let Some(target) = Target::named(&name) else {
        eprintln!("set CANDELA_FUZZ_TARGET to one of {:?}", names());
        std::process::exit(2);
    };
    afl::fuzz!(|data: &[u8]| {
        let _ = run(target, data);
    });
}

fn names() -> Vec<&'static str> {
    Target::ALL.iter().map(|t| t.name()).collect()
}

fn write_seeds(args: &[String]) -> i32 {
    let (Some(name), Some(dir)) = (args.first(), args.get(1)) else {
        eprintln!("usage: candela_fuzz --write-seeds <target> <dir>");
        return 2;
    };
    let Some(target) = Target::named(name) else {
        eprintln!("unknown target {name:?}; targets: {:?}", names());
        return 2;
    };
    let dir = std::path::Path::new(dir);
    if let Err(e) = std::fs::create_dir_all(dir) {
        eprintln!("cannot create {}: {e}", dir.display());
        return 1;
    }
    for (i, (_, bytes)) in seeds(target).iter().enumerate() {
        let path = dir.join(format!("seed_{i:03}"));
        if let Err(e) = std::fs::write(&path, bytes) {
            eprintln!("cannot write {}: {e}", path.display());
            return 1;
        }
    }
    0
}
