//! MTL parsing: the text of a Wavefront material library in, [`MtlMaterial`] records out,
//! exactly as written (no interpretation; `mtl_material` maps them to engine materials).
//!
//! Keywords are matched case-insensitively. Read: `newmtl`, `Kd`, `Ks`, `Ke`, `Tf`
//! (colours: one value means grey), `Ns`, `Ni`, `d` (with or without `-halo`), `Tr`, `Pr`,
//! `Pm`, `illum`, and the textures `map_Kd`, `map_Ke`, `bump`/`map_bump`, `norm` with their
//! options (`-bm` and `-clamp` are kept, the other standard options are skipped; the file name
//! is the rest of the line and may contain spaces). Everything else is listed in
//! [`MtlMaterial::ignored`] so that the loader can say what it did not use.
//! Non-numeric or non-finite numbers are errors (with the line number).
//! Must not: read files or resolve paths.

use glam::Vec3;

/// One texture statement of an MTL material.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct MtlTexture {
    /// The file name as written (relative to the MTL file's folder).
    pub file: String,
    /// `-bm`: bump multiplier (1 when absent).
    pub bump_multiplier: f32,
    /// `-clamp on`: clamp texture coordinates instead of repeating.
    pub clamp: bool,
}

/// One `newmtl` block, as written.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct MtlMaterial {
    pub name: String,
    pub kd: Option<Vec3>,
    pub ks: Option<Vec3>,
    pub ke: Option<Vec3>,
    pub tf: Option<Vec3>,
    pub ns: Option<f32>,
    pub ni: Option<f32>,
    pub d: Option<f32>,
    pub tr: Option<f32>,
    pub pr: Option<f32>,
    pub pm: Option<f32>,
    pub illum: Option<u32>,
    pub map_kd: Option<MtlTexture>,
    pub map_ke: Option<MtlTexture>,
    /// `bump` or `map_bump`: often a height map (see `texture::Usage::Bump`).
    pub bump: Option<MtlTexture>,
    /// `norm`: a tangent-space normal map.
    pub norm: Option<MtlTexture>,
    /// Statements read but not used (keyword only), for a note.
    pub ignored: Vec<String>,
}

/// Parses an MTL file's text. Errors are "line N: problem".
pub(crate) fn parse_mtl(text: &str) -> Result<Vec<MtlMaterial>, String> {
    let mut materials: Vec<MtlMaterial> = Vec::new();
    for (number, line) in text.lines().enumerate() {
        let line = line.trim();
        let (keyword, rest) = line
            .split_once(char::is_whitespace)
            .map_or((line, ""), |(k, r)| (k, r.trim()));
        if keyword.is_empty() || keyword.starts_with('#') {
            continue;
        }
        let keyword = keyword.to_ascii_lowercase();
        let fail = |problem: String| format!("line {}: {keyword}: {problem}", number + 1);
        if keyword == "newmtl" {
            if rest.is_empty() {
                return Err(fail("a material needs a name".to_string()));
            }
            materials.push(MtlMaterial {
                name: rest.to_string(),
                ..MtlMaterial::default()
            });
            continue;
        }
        // Statements before the first `newmtl` belong to no material.
        let Some(material) = materials.last_mut() else {
            continue;
        };
        match keyword.as_str() {
            "kd" => material.kd = parse_color(rest).map_err(fail)?,
            "ks" => material.ks = parse_color(rest).map_err(fail)?,
            "ke" => material.ke = parse_color(rest).map_err(fail)?,
            "tf" => material.tf = parse_color(rest).map_err(fail)?,
            "ns" => material.ns = Some(parse_number(rest).map_err(fail)?),
            "ni" => material.ni = Some(parse_number(rest).map_err(fail)?),
            "d" => {
                let value = rest.strip_prefix("-halo").map_or(rest, str::trim);
                material.d = Some(parse_number(value).map_err(fail)?);
            }
            "tr" => material.tr = Some(parse_number(rest).map_err(fail)?),
            "pr" => material.pr = Some(parse_number(rest).map_err(fail)?),
            "pm" => material.pm = Some(parse_number(rest).map_err(fail)?),
            "illum" => {
                let value = rest.split_whitespace().next().unwrap_or("");
                material.illum = Some(
                    value
                        .parse()
                        .map_err(|_| fail(format!("{value:?} is not a whole number")))?,
                );
            }
            "map_kd" => material.map_kd = Some(parse_texture(rest).map_err(fail)?),
            "map_ke" => material.map_ke = Some(parse_texture(rest).map_err(fail)?),
            "bump" | "map_bump" => material.bump = Some(parse_texture(rest).map_err(fail)?),
            "norm" => material.norm = Some(parse_texture(rest).map_err(fail)?),
            // Ambient colour: meaningless in a path tracer; not worth a note.
            "ka" | "map_ka" => {}
            _ => {
                if !material.ignored.contains(&keyword) {
                    material.ignored.push(keyword.clone());
                }
            }
        }
    }
    Ok(materials)
}

/// One finite number.
fn parse_number(text: &str) -> Result<f32, String> {
    let token = text.split_whitespace().next().unwrap_or("");
    match token.parse::<f32>() {
        Ok(value) if value.is_finite() => Ok(value),
        Ok(_) => Err(format!("{token:?} is not finite")),
        Err(_) => Err(format!("{token:?} is not a number")),
    }
}

/// `r [g b]` (one value means grey). `spectral` and `xyz` forms are not supported: `None`.
fn parse_color(text: &str) -> Result<Option<Vec3>, String> {
    let tokens: Vec<&str> = text.split_whitespace().collect();
    if matches!(tokens.first(), Some(&"spectral") | Some(&"xyz")) {
        return Ok(None);
    }
    let values = tokens
        .iter()
        .take(3)
        .map(|token| parse_number(token))
        .collect::<Result<Vec<f32>, String>>()?;
    match values.as_slice() {
        [grey] => Ok(Some(Vec3::splat(*grey))),
        [r, g, b] => Ok(Some(Vec3::new(*r, *g, *b))),
        _ => Err(format!("expected 1 or 3 numbers, found {:?}", text)),
    }
}

/// How many arguments a texture option takes (`-o`, `-s`, `-t` take one to three numbers).
fn option_arity(option: &str) -> Option<(usize, usize)> {
    match option {
        "-blendu" | "-blendv" | "-cc" | "-clamp" | "-bm" | "-boost" | "-texres" | "-imfchan"
        | "-type" | "-colorspace" => Some((1, 1)),
        "-mm" => Some((2, 2)),
        "-o" | "-s" | "-t" => Some((1, 3)),
        _ => None,
    }
}

/// `[options] file name with spaces`.
fn parse_texture(text: &str) -> Result<MtlTexture, String> {
    let mut texture = MtlTexture {
        file: String::new(),
        bump_multiplier: 1.0,
        clamp: false,
    };
    let mut rest = text.trim_start();
    while let Some((option, (min, max))) = rest
        .split_whitespace()
        .next()
        .and_then(|option| option_arity(option).map(|arity| (option, arity)))
    {
        rest = rest[option.len()..].trim_start();
        let mut arguments = Vec::new();
        while arguments.len() < max {
            let Some(token) = rest.split_whitespace().next() else {
                break;
            };
            if arguments.len() >= min && token.parse::<f32>().is_err() {
                break;
            }
            arguments.push(token);
            rest = rest[token.len()..].trim_start();
        }
        if arguments.len() < min {
            return Err(format!("option {option} needs {min} argument(s)"));
        }
        match option {
            "-bm" => texture.bump_multiplier = parse_number(arguments[0])?,
            "-clamp" => texture.clamp = arguments[0].eq_ignore_ascii_case("on"),
            _ => {}
        }
    }
    texture.file = rest.trim().to_string();
    if texture.file.is_empty() {
        return Err("no texture file name".to_string());
    }
    Ok(texture)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_colours_numbers_and_texture_options() -> Result<(), String> {
        let text = "# c\nKd 9 9 9\nnewmtl glass\nKd 0.5\nTf 1 0.5 0.25\nNi 1.5\nd -halo 0.25\n\
                    illum 7\nmap_Kd -s 1 1 1 -clamp on my texture.png\nbump -bm 0.3 h.png\n\
                    map_Ks spec.png\nnewmtl b\n";
        let materials = parse_mtl(text)?;
        assert_eq!(materials.len(), 2);
        let glass = &materials[0];
        assert_eq!(glass.kd, Some(Vec3::splat(0.5)));
        assert_eq!(glass.tf, Some(Vec3::new(1.0, 0.5, 0.25)));
        assert_eq!(
            (glass.ni, glass.d, glass.illum),
            (Some(1.5), Some(0.25), Some(7))
        );
        let map = glass.map_kd.as_ref().ok_or("map_Kd")?;
        assert_eq!((map.file.as_str(), map.clamp), ("my texture.png", true));
        assert_eq!(glass.bump.as_ref().map(|b| b.bump_multiplier), Some(0.3));
        assert_eq!(glass.ignored, vec!["map_ks".to_string()]);
        assert_eq!(materials[1].name, "b");
        Ok(())
    }

    #[test]
    fn refuses_bad_numbers_with_the_line() {
        for (text, line) in [
            ("newmtl a\nKd nan 0 0", "line 2"),
            ("newmtl a\n\nNs x", "line 3"),
        ] {
            match parse_mtl(text) {
                Err(message) => assert!(message.starts_with(line), "{message}"),
                Ok(_) => panic!("{text:?} was accepted"),
            }
        }
    }
}
