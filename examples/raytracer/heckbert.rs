//! Light-path filters in Heckbert's notation (seed 000: "L is light, S specular, D diffuse,
//! E eye"; Heckbert 1990, "Adaptive radiosity textures for bidirectional ray tracing").
//!
//! A path is written from the light to the eye, one letter per vertex: `L`, then `D` for a
//! diffuse or glossy bounce and `S` for a specular (delta) one, then `E`. A filter is a
//! regular expression over those letters: juxtaposition, `|`, `*`, `+`, `?`, grouping with
//! `( )`, and `{SD}` or `[SD]` for "one of". `.` is any vertex. Spaces are ignored and
//! letters are case-insensitive. The expression must match the whole path.

use regex::bytes::Regex;

/// A compiled light-path filter.
#[derive(Clone, Debug)]
pub struct PathFilter {
    /// The expression translated to an anchored regular expression over path labels.
    regex: Regex,
}

/// The label of a diffuse or glossy bounce.
pub const DIFFUSE: u8 = b'D';
/// The label of a specular bounce.
pub const SPECULAR: u8 = b'S';

impl PathFilter {
    /// Parses `expr`.
    ///
    /// # Errors
    /// A message naming the offending character or the syntax error.
    pub fn parse(expr: &str) -> Result<Self, String> {
        let mut pattern = String::from("^(?:");
        let mut in_set = false;
        for c in expr.chars() {
            match c.to_ascii_uppercase() {
                c if c.is_whitespace() => {}
                c @ ('L' | 'D' | 'S' | 'E') => pattern.push(c),
                '.' if !in_set => pattern.push_str("[LDSE]"),
                c @ ('+' | '*' | '?' | '|' | ')') if !in_set => pattern.push(c),
                '(' if !in_set => pattern.push_str("(?:"),
                '{' | '[' if !in_set => {
                    in_set = true;
                    pattern.push('[');
                }
                '}' | ']' if in_set => {
                    in_set = false;
                    pattern.push(']');
                }
                other => {
                    return Err(format!(
                        "unexpected '{other}' in the path expression {expr:?}: use L, D, S, E, \
                         ( ), |, *, +, ?, . and {{…}} or […] for a set"
                    ));
                }
            }
        }
        if in_set {
            return Err(format!("unclosed set in the path expression {expr:?}"));
        }
        if pattern.ends_with("(?:") {
            return Err("the path expression is empty".to_owned());
        }
        pattern.push_str(")$");
        let regex = Regex::new(&pattern).map_err(|e| {
            format!(
                "invalid path expression {expr:?}: {}",
                last_line(&e.to_string())
            )
        })?;
        Ok(Self { regex })
    }

    /// True when the path `L`, `last`, then the camera path's `bounces` read from the light
    /// back to the eye, then `E`, matches. `bounces` is in the order the camera path made
    /// them (eye first); `last` is the label of the vertex that connected to the light, if
    /// it is not already in `bounces`.
    pub fn accepts(&self, last: Option<u8>, bounces: &[u8]) -> bool {
        let mut path = Vec::with_capacity(bounces.len() + 3);
        path.push(b'L');
        path.extend(last);
        path.extend(bounces.iter().rev());
        path.push(b'E');
        self.regex.is_match(&path)
    }
}

/// The last line of a multi-line message: the regex crate ends with the error itself, after
/// a diagram of the translated pattern, which would confuse the user.
fn last_line(s: &str) -> &str {
    s.lines().last().unwrap_or(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn accepts(expr: &str, path_light_to_eye: &str) -> bool {
        // The camera path's bounces are the middle letters, eye first.
        let middle: Vec<u8> = path_light_to_eye.bytes().skip(1).rev().skip(1).collect();
        PathFilter::parse(expr).unwrap().accepts(None, &middle)
    }

    #[test]
    fn heckbert_expressions_match_whole_paths() {
        assert!(accepts("L D E", "LDE"));
        assert!(!accepts("L D E", "LDDE"));
        assert!(accepts("L S+ D E", "LSSDE"));
        assert!(!accepts("L S+ D E", "LDE"));
        assert!(accepts("L (S|D)* E", "LE"));
        assert!(accepts("L{SD}+E", "LSDSE"));
        assert!(accepts("l [sd] e", "LSE"));
        assert!(accepts("L.*E", "LDSDE"));
        assert!(accepts("LD?E", "LE"));
    }

    #[test]
    fn last_vertex_is_next_to_the_light() {
        let f = PathFilter::parse("L D S E").unwrap();
        // The camera hit a mirror (S) then a diffuse vertex that connected to the light.
        assert!(f.accepts(Some(DIFFUSE), &[SPECULAR]));
        assert!(!f.accepts(Some(SPECULAR), &[DIFFUSE]));
    }

    #[test]
    fn bad_expressions_are_refused_with_a_message() {
        for bad in ["L X E", "L (D E", "", "L {D E", "*", "L ) E"] {
            let err = PathFilter::parse(bad).unwrap_err();
            assert!(!err.is_empty(), "{bad}");
        }
    }
}
