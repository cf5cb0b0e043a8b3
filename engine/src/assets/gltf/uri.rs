//! glTF URIs: a `data:` URI is decoded in place; anything else must be a relative reference,
//! percent-decoded into a file name that the caller resolves inside the asset root.
//!
//! Must not: read files (the caller resolves and reads relative references).

/// What a glTF `uri` points to.
pub(crate) enum UriTarget {
    /// The bytes of a `data:` URI.
    Embedded(Vec<u8>),
    /// A relative reference, percent-decoded (`/`-separated).
    Relative(String),
}

/// Decodes `uri`; errors say why it cannot be used.
pub(crate) fn parse_uri(uri: &str) -> Result<UriTarget, String> {
    if let Some(rest) = uri.strip_prefix("data:") {
        let (header, data) = rest
            .split_once(',')
            .ok_or_else(|| "a data URI without a comma".to_string())?;
        return if header.ends_with(";base64") {
            base64::decode(data.trim())
                .map(UriTarget::Embedded)
                .map_err(|e| format!("bad base64 in a data URI: {e}"))
        } else {
            Ok(UriTarget::Embedded(
                urlencoding::decode_binary(data.as_bytes()).into_owned(),
            ))
        };
    }
    if let Some((scheme, _)) = uri.split_once(':') {
        let is_scheme = scheme.len() > 1
            && scheme.starts_with(|c: char| c.is_ascii_alphabetic())
            && scheme
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || matches!(c, '+' | '-' | '.'));
        if is_scheme {
            return Err(format!(
                "URI scheme {scheme:?} is not supported (only relative paths and data: URIs)"
            ));
        }
    }
    let decoded = urlencoding::decode(uri)
        .map_err(|_| format!("URI {uri:?} is not valid percent-encoded UTF-8"))?;
    Ok(UriTarget::Relative(decoded.into_owned()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decodes_data_uris_and_percent_encoding() {
        let decoded = |uri: &str| match parse_uri(uri) {
            Ok(UriTarget::Embedded(bytes)) => format!("bytes {bytes:?}"),
            Ok(UriTarget::Relative(path)) => format!("path {path}"),
            Err(_) => "error".to_string(),
        };
        assert_eq!(
            decoded("data:application/octet-stream;base64,AAEC"),
            "bytes [0, 1, 2]"
        );
        assert_eq!(decoded("data:,a%20b"), "bytes [97, 32, 98]");
        assert_eq!(
            decoded("Box%20With%20Spaces.bin"),
            "path Box With Spaces.bin"
        );
        assert_eq!(decoded(" 2x2 image  has.png"), "path  2x2 image  has.png");
        assert_eq!(decoded("https://example.com/a.bin"), "error");
        assert_eq!(decoded("data:;base64,@@"), "error");
    }
}
