//! Quoting the user's text inside an error message, written once for every reader.
//!
//! A token echoed in an error can be anything a hostile or broken file holds: a million
//! characters, terminal escape sequences, bidirectional overrides, a NUL byte. [`quote`]
//! makes it short and inert, so the one `error:` line stays one short line.

use std::fmt::Write;

/// How many characters of a token (after escaping) an error message shows.
pub(crate) const QUOTE_LIMIT: usize = 40;

/// `token` as error messages show it: in double quotes, with every character that does not
/// print as itself escaped the way Rust's `char::escape_debug` does (control characters as
/// `\n`, `\t`, `\u{1b}`, format characters such as U+202E as `\u{202e}`, `"` and `\` with a
/// backslash), and cut after [`QUOTE_LIMIT`] characters of that escaped form, followed by
/// `…` and the token's full length in characters: `"aaaa"… (1000000 characters)`.
///
/// The work is linear in the token's length (counting its characters is the only pass
/// beyond the shown prefix).
pub(crate) fn quote(token: &str) -> String {
    let mut out = String::with_capacity(QUOTE_LIMIT + 32);
    out.push('"');
    let mut shown = 0;
    let mut cut = false;
    let mut piece = String::new();
    for c in token.chars() {
        piece.clear();
        if c == '\'' {
            // Inside double quotes a single quote needs no escape.
            piece.push(c);
        } else {
            piece.extend(c.escape_debug());
        }
        let width = piece.chars().count();
        if shown + width > QUOTE_LIMIT {
            cut = true;
            break;
        }
        out.push_str(&piece);
        shown += width;
    }
    out.push('"');
    if cut {
        let total = token.chars().count();
        // Writing to a String cannot fail.
        let _ = write!(out, "… ({total} characters)");
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_tokens_are_quoted_whole() {
        assert_eq!(quote(""), "\"\"");
        assert_eq!(quote("abc"), "\"abc\"");
        assert_eq!(quote("1/3"), "\"1/3\"");
        assert_eq!(quote("it's"), "\"it's\"");
        assert_eq!(quote("say \"hi\""), "\"say \\\"hi\\\"\"");
        assert_eq!(quote("a\\b"), "\"a\\\\b\"");
        assert_eq!(quote("café"), "\"café\"");
        let exactly = "x".repeat(QUOTE_LIMIT);
        assert_eq!(quote(&exactly), format!("\"{exactly}\""));
    }

    #[test]
    fn control_and_format_characters_are_escaped() {
        assert_eq!(quote("\u{1b}[31mred"), "\"\\u{1b}[31mred\"");
        assert_eq!(quote("a\nb\tc\r\0"), "\"a\\nb\\tc\\r\\0\"");
        assert_eq!(quote("\u{202e}evil"), "\"\\u{202e}evil\"");
        assert_eq!(quote("\u{7f}\u{85}"), "\"\\u{7f}\\u{85}\"");
        let q = quote("\u{1}\u{2}\u{3}\u{1f}");
        assert!(q.chars().all(|c| !c.is_control()), "{q:?}");
    }

    #[test]
    fn long_tokens_are_cut_and_their_length_given() {
        let long = "a".repeat(1_000_000);
        let q = quote(&long);
        assert_eq!(
            q,
            format!("\"{}\"… (1000000 characters)", "a".repeat(QUOTE_LIMIT))
        );
        // One more character than the limit is cut too.
        let over = "b".repeat(QUOTE_LIMIT + 1);
        assert_eq!(
            quote(&over),
            format!("\"{}\"… (41 characters)", "b".repeat(QUOTE_LIMIT))
        );
        // The limit counts the escaped form: escapes are never split.
        let escapes = "\u{1b}".repeat(100);
        let q = quote(&escapes);
        let shown = q.split('"').nth(1).unwrap();
        assert_eq!(shown, "\\u{1b}".repeat(QUOTE_LIMIT / 6));
        assert!(q.ends_with("… (100 characters)"), "{q}");
        // Characters, not bytes: multi-byte text is counted and cut on character bounds.
        let wide = "é".repeat(50);
        assert_eq!(
            quote(&wide),
            format!("\"{}\"… (50 characters)", "é".repeat(QUOTE_LIMIT))
        );
    }
}
