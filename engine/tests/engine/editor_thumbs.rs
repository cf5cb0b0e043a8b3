//! Palette thumbnails (issue 33): a red cube's thumbnail, rendered by the engine's CPU tracer
//! on the thumbnail thread, is not blank (its pixels vary, and red shows where the cube is),
//! is cached on disk by the model file's content hash, and a second `Thumbnails` over the
//! same cache reads it back without rendering; a model file that does not load gets a
//! placeholder and a message naming it, not a panic.

use crate::editor_common;

use candela::assets::AssetRoot;
use candela::editor::{Shown, THUMB_PIXELS, Thumbnails, content_hash};
use editor_common::Scratch;

const CUBE: &str = "mtllib red.mtl\nusemtl red\n\
v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5\n\
v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 0.5 0.5\n\
f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n\
f 4 7 3\nf 4 8 7\nf 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n";

#[test]
fn a_thumbnail_shows_the_model_is_cached_by_content_and_a_broken_model_gets_a_placeholder()
-> anyhow::Result<()> {
    let scratch = Scratch::new("editor_thumbs");
    let kit = scratch.path().join("kit");
    std::fs::create_dir_all(&kit)?;
    std::fs::write(kit.join("red.obj"), CUBE)?;
    std::fs::write(kit.join("red.mtl"), "newmtl red\nKd 0.8 0.05 0.05\n")?;
    std::fs::write(kit.join("broken.obj"), "v 0 0 0\nf 1 2 9\n")?;
    let cache = scratch.path().join("cache");
    let ctx = egui::Context::default();
    let root = AssetRoot::new(scratch.path())?;

    let mut thumbs = Thumbnails::new(root.clone(), cache.clone());
    assert!(matches!(thumbs.shown("kit/red.obj"), Shown::Pending));
    thumbs.shown("kit/broken.obj");
    thumbs.wait(&ctx);
    assert!(matches!(thumbs.shown("kit/red.obj"), Shown::Ready(_)));
    assert_eq!((thumbs.rendered, thumbs.from_disk), (1, 0));
    match thumbs.shown("kit/broken.obj") {
        Shown::Failed(why) => assert!(why.contains("broken.obj"), "{why}"),
        _ => panic!("the broken model has a placeholder"),
    }
    assert_eq!(thumbs.messages.len(), 1, "{:?}", thumbs.messages);
    assert!(thumbs.messages[0].contains("kit/broken.obj"));

    // The cached picture: named by the file's content hash; not blank; red where the cube is.
    let key = content_hash(&std::fs::read(kit.join("red.obj"))?);
    let png = cache.join(format!("{key:016x}-{THUMB_PIXELS}.png"));
    let img = image::open(&png)?.to_rgb8();
    assert_eq!(img.dimensions(), (THUMB_PIXELS, THUMB_PIXELS));
    let luma: Vec<f64> = (img.pixels())
        .map(|p| (f64::from(p[0]) + f64::from(p[1]) + f64::from(p[2])) / 3.0)
        .collect();
    let mean = luma.iter().sum::<f64>() / luma.len() as f64;
    let sd = (luma.iter().map(|l| (l - mean).powi(2)).sum::<f64>() / luma.len() as f64).sqrt();
    let red = (img.pixels())
        .filter(|p| {
            i32::from(p[0]) > i32::from(p[1]) + 40 && i32::from(p[0]) > i32::from(p[2]) + 40
        })
        .count();
    let share = red as f64 / luma.len() as f64;
    eprintln!("luma mean {mean:.1}, sd {sd:.1}; red on {share:.3} of the pixels");
    assert!(sd > 10.0, "the pixels vary: sd {sd:.1}");
    assert!(share > 0.1, "the cube's red shows: {share:.3}");

    // A second open reads the cache: no render.
    let mut again = Thumbnails::new(root, cache);
    again.shown("kit/red.obj");
    again.wait(&ctx);
    assert!(matches!(again.shown("kit/red.obj"), Shown::Ready(_)));
    assert_eq!(
        (again.rendered, again.from_disk),
        (0, 1),
        "read from the disk cache"
    );
    Ok(())
}
