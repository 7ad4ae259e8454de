//! Recovers STEP entity ids (`#123`) for the entity types we report by id.
//!
//! step-io keeps each entity type in an arena in id order but does not keep
//! the ids themselves. A light scan of the file's `#id = KEYWORD(` headers
//! (skipping strings and comments) gives, per keyword, the ids in ascending
//! order; minus the ids step-io dropped, the i-th id is the i-th arena
//! entry. The reader checks the counts agree before trusting the mapping.

use std::collections::HashMap;

/// The keywords whose ids are recovered.
pub const KEYWORDS: &[&str] = &[
    "ADVANCED_FACE",
    "FACE_SURFACE",
    "EDGE_CURVE",
    "VERTEX_POINT",
    "MANIFOLD_SOLID_BREP",
    "BREP_WITH_VOIDS",
    "CLOSED_SHELL",
    "OPEN_SHELL",
    "SHELL_BASED_SURFACE_MODEL",
];

/// Ascending entity ids per keyword (only [`KEYWORDS`]).
pub fn scan_ids(bytes: &[u8]) -> HashMap<&'static str, Vec<u64>> {
    let mut out: HashMap<&'static str, Vec<u64>> = KEYWORDS.iter().map(|k| (*k, vec![])).collect();
    let n = bytes.len();
    let mut i = 0;
    // Only the DATA section holds instances; the header has none with '#'.
    let mut at_statement_start = true;
    while i < n {
        let b = bytes[i];
        match b {
            b'\'' => {
                // String: '' is an escaped quote.
                i += 1;
                while i < n {
                    if bytes[i] == b'\'' {
                        if i + 1 < n && bytes[i + 1] == b'\'' {
                            i += 2;
                            continue;
                        }
                        break;
                    }
                    i += 1;
                }
                i += 1;
                at_statement_start = false;
            }
            b'/' if i + 1 < n && bytes[i + 1] == b'*' => {
                i += 2;
                while i + 1 < n && !(bytes[i] == b'*' && bytes[i + 1] == b'/') {
                    i += 1;
                }
                i += 2;
            }
            b';' => {
                at_statement_start = true;
                i += 1;
            }
            b'#' if at_statement_start => {
                at_statement_start = false;
                let mut j = i + 1;
                let mut id: u64 = 0;
                let mut digits = 0;
                while j < n && bytes[j].is_ascii_digit() {
                    id = id
                        .saturating_mul(10)
                        .saturating_add(u64::from(bytes[j] - b'0'));
                    j += 1;
                    digits += 1;
                }
                while j < n && bytes[j].is_ascii_whitespace() {
                    j += 1;
                }
                if digits == 0 || j >= n || bytes[j] != b'=' {
                    i = j.max(i + 1);
                    continue;
                }
                j += 1;
                while j < n && bytes[j].is_ascii_whitespace() {
                    j += 1;
                }
                let start = j;
                while j < n && (bytes[j].is_ascii_alphanumeric() || bytes[j] == b'_') {
                    j += 1;
                }
                if let Ok(kw) = std::str::from_utf8(&bytes[start..j]) {
                    if let Some(list) = KEYWORDS
                        .iter()
                        .find(|k| k.eq_ignore_ascii_case(kw))
                        .and_then(|k| out.get_mut(k))
                    {
                        list.push(id);
                    }
                }
                i = j;
            }
            c if c.is_ascii_whitespace() => i += 1,
            _ => {
                at_statement_start = false;
                i += 1;
            }
        }
    }
    for v in out.values_mut() {
        v.sort_unstable();
        v.dedup();
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_ids_and_skips_strings_and_comments() {
        let src = b"DATA;\n#10 = ADVANCED_FACE('a;#11=EDGE_CURVE(',(#2),#3,.T.);\n\
                    /* #12=EDGE_CURVE() */ #7=EDGE_CURVE('it''s',#1,#2,#3,.T.);\n\
                    #5 = ( BOUNDED_CURVE() );#3=ADVANCED_FACE('',(),#1,.F.);ENDSEC;";
        let ids = scan_ids(src);
        assert_eq!(ids["ADVANCED_FACE"], vec![3, 10]);
        assert_eq!(ids["EDGE_CURVE"], vec![7]);
        assert!(ids["VERTEX_POINT"].is_empty());
    }
}
