//! `assetgen demo [--out FILE]`: writes the demo level (default
//! `assets/test_scenes/demo/demo.ron`, relative to the current folder). See `assetgen::demo_level`.
//! `assetgen sounds [--out DIR]`: writes the games' sounds as WAV files (default
//! `assets/common/sounds`). See `assetgen::sounds`.
//! `assetgen ruins-sounds [--out DIR]`: writes It's About Time's sounds (default
//! `assets/its_about_time/sounds`). See `assetgen::ruins_sound_list`.
//! `assetgen reflect-kit [--out DIR]`: writes the Reflect art kit (default
//! `assets/reflect/kit`), glTF + PNG. See `assetgen::reflect_kit`.
//! `assetgen ruins-kit [--out DIR]`: writes the It's About Time art kit (default
//! `assets/its_about_time/kit`), glTF + PNG. See `assetgen::ruins_kit`.
//! `assetgen hero [--out DIR]`: writes the skinned hero (default `assets/common/hero`),
//! `hero.glb`. See `assetgen::hero`.

use std::path::PathBuf;

use anyhow::Context;
use clap::{Parser, Subcommand};

#[derive(Parser, Debug)]
#[command(name = "assetgen", about = "Generates Candela's own assets")]
struct Args {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// The demo city level.
    Demo {
        #[arg(long, default_value = "assets/test_scenes/demo/demo.ron")]
        out: PathBuf,
    },
    /// The games' sounds (mono 16-bit WAV, synthesised).
    Sounds {
        #[arg(long, default_value = "assets/common/sounds")]
        out: PathBuf,
    },
    /// It's About Time's sounds (mono 16-bit WAV, synthesised).
    RuinsSounds {
        #[arg(long, default_value = "assets/its_about_time/sounds")]
        out: PathBuf,
    },
    /// The Reflect art kit (glTF pieces and their PNG textures).
    ReflectKit {
        #[arg(long, default_value = "assets/reflect/kit")]
        out: PathBuf,
    },
    /// The It's About Time art kit (glTF pieces, colour and normal-map PNGs).
    RuinsKit {
        #[arg(long, default_value = "assets/its_about_time/kit")]
        out: PathBuf,
    },
    /// The skinned, animated hero (one GLB).
    Hero {
        #[arg(long, default_value = "assets/common/hero")]
        out: PathBuf,
    },
}

fn main() -> anyhow::Result<()> {
    match Args::parse().command {
        Command::Demo { out } => {
            let text = assetgen::demo_ron()?;
            if let Some(dir) = out.parent().filter(|d| !d.as_os_str().is_empty()) {
                std::fs::create_dir_all(dir)
                    .with_context(|| format!("cannot create {}", dir.display()))?;
            }
            std::fs::write(&out, text)
                .with_context(|| format!("cannot write {}", out.display()))?;
            println!("wrote {}", out.display());
            Ok(())
        }
        Command::Sounds { out } => write_sounds(&out, assetgen::sounds::sound_files()),
        Command::RuinsSounds { out } => {
            write_sounds(&out, assetgen::ruins_sound_list::ruins_sound_files())
        }
        Command::ReflectKit { out } => {
            write_kit(&out, &assetgen::reflect_kit::kit_files()?)?;
            for piece in assetgen::reflect_kit::pieces() {
                print_piece(&piece);
            }
            Ok(())
        }
        Command::RuinsKit { out } => {
            write_kit(&out, &assetgen::ruins_kit::kit_files()?)?;
            for piece in assetgen::ruins_kit::pieces() {
                print_piece(&piece);
            }
            Ok(())
        }
        Command::Hero { out } => {
            std::fs::create_dir_all(&out)
                .with_context(|| format!("cannot create {}", out.display()))?;
            for (file, bytes) in assetgen::hero::hero_files()? {
                let path = out.join(file);
                std::fs::write(&path, &bytes)
                    .with_context(|| format!("cannot write {}", path.display()))?;
                println!("wrote {} ({} bytes)", path.display(), bytes.len());
            }
            println!("  {} triangles", assetgen::hero::triangle_count());
            Ok(())
        }
    }
}

/// Writes `(file name, WAV bytes)` sounds into `out` and names each.
fn write_sounds(out: &std::path::Path, files: Vec<(String, Vec<u8>)>) -> anyhow::Result<()> {
    std::fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))?;
    for (file, bytes) in files {
        let path = out.join(file);
        std::fs::write(&path, &bytes)
            .with_context(|| format!("cannot write {}", path.display()))?;
        println!("wrote {} ({} bytes)", path.display(), bytes.len());
    }
    Ok(())
}

/// Writes a kit's `(relative path, bytes)` files under `out` and says how much it wrote.
fn write_kit(out: &std::path::Path, files: &[(String, Vec<u8>)]) -> anyhow::Result<()> {
    for (file, bytes) in files {
        let path = out.join(file);
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir)
                .with_context(|| format!("cannot create {}", dir.display()))?;
        }
        std::fs::write(&path, bytes).with_context(|| format!("cannot write {}", path.display()))?;
    }
    let total: usize = files.iter().map(|(_, b)| b.len()).sum();
    println!(
        "wrote {} files ({total} bytes) to {}",
        files.len(),
        out.display()
    );
    Ok(())
}

fn print_piece(piece: &assetgen::reflect_kit::Piece) {
    println!(
        "  {:<22} {:>5} triangles, {:>4} emissive",
        piece.name,
        piece.triangle_count(),
        piece.emissive_triangle_count()
    );
}
