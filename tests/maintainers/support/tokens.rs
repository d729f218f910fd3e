//! Machinery a student need not read: counts a Rust file's tokens and non-blank lines by the rules
//! of the team's `size.py` (kept beside this repository, not in it), for the README's size guard.
//! Comments are stripped; each name, number, string or char literal, lifetime, operator and bracket
//! is one token; `:: -> => == != <= >= && || += -= *= /= %= ^= &= |= <<= >>= << >> ..= ... .. ++ --`
//! are one each. Lines are counted as the file is, which CI checks is formatted by `cargo fmt`.

/// The source without its comments: `//` to the end of the line goes, `/* */` becomes a space, and a
/// `"` string is kept whole (a `//` inside it is no comment). As in size.py, char literals and raw
/// strings get no special care: `'"'` would start a string.
pub fn strip_comments(source: &str) -> String {
    let chars: Vec<char> = source.chars().collect();
    let starts = |i: usize, text: &str| {
        text.chars()
            .enumerate()
            .all(|(k, c)| chars.get(i + k) == Some(&c))
    };
    let mut kept = String::new();
    let mut i = 0;
    while i < chars.len() {
        if starts(i, "//") {
            while i < chars.len() && chars[i] != '\n' {
                i += 1;
            }
        } else if starts(i, "/*") {
            i += 2;
            while i < chars.len() && !starts(i, "*/") {
                i += 1;
            }
            i += 2;
            kept.push(' ');
        } else if chars[i] == '"' {
            let start = i;
            i += 1;
            while i < chars.len() && chars[i] != '"' {
                i += if chars[i] == '\\' { 2 } else { 1 };
            }
            i += 1;
            kept.extend(&chars[start..i.min(chars.len())]);
        } else {
            kept.push(chars[i]);
            i += 1;
        }
    }
    kept
}

/// The operators that count as one token, longest first so that `<<=` is not read as `<<` and `=`.
const OPERATORS: [&str; 26] = [
    "<<=", ">>=", "..=", "...", "::", "->", "=>", "==", "!=", "<=", ">=", "&&", "||", "+=", "-=",
    "*=", "/=", "%=", "^=", "&=", "|=", "<<", ">>", "..", "++", "--",
];

/// How many characters of `text` from `from` on satisfy `test`.
fn run(text: &[char], from: usize, test: impl Fn(char) -> bool) -> usize {
    text.iter().skip(from).take_while(|&&c| test(c)).count()
}

/// `\w` and `\d` of a regular expression.
fn word(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

fn digit(c: char) -> bool {
    c.is_ascii_digit()
}

/// The length of an exponent (`e` or `E`, a sign or none, digits) at `k`, or 0 where there is none.
fn exponent(text: &[char], k: usize) -> usize {
    if !matches!(text.get(k), Some('e' | 'E')) {
        return 0;
    }
    let sign = usize::from(matches!(text.get(k + 1), Some('+' | '-')));
    match run(text, k + 1 + sign, digit) {
        0 => 0,
        digits => 1 + sign + digits,
    }
}

/// The length of the token at the start of `text`, tried in size.py's order: raw string, string,
/// char literal, lifetime, hex number, number, number from its point, name, operator, any other
/// character (which is also what a string or literal without its end counts as).
fn token_length(text: &[char]) -> usize {
    let at = |k: usize| text.get(k).copied();
    let first = text[0];
    // A raw string r#"..."#: r, any #s, a quote, up to the next quote, then any #s.
    let hashes = run(text, 1, |c| c == '#');
    if first == 'r' && at(1 + hashes) == Some('"') {
        let body = run(text, 2 + hashes, |c| c != '"');
        if at(2 + hashes + body).is_some() {
            let close = 2 + hashes + body;
            return close + 1 + run(text, close + 1, |c| c == '#');
        }
    }
    // A string: escapes are a backslash and any character but a line break.
    if first == '"' {
        let mut k = 1;
        loop {
            match (at(k), at(k + 1)) {
                (Some('"'), _) => return k + 1,
                (Some('\\'), Some(c)) if c != '\n' => k += 2,
                (Some(c), _) if c != '\\' => k += 1,
                _ => return 1,
            }
        }
    }
    if first == '\'' {
        let char_literal = match (at(1), at(2), at(3)) {
            (Some('\\'), Some(c), Some('\'')) if c != '\n' => 4,
            (Some(c), Some('\''), _) if c != '\\' && c != '\'' => 3,
            _ => 0,
        };
        if char_literal > 0 {
            return char_literal;
        }
        if at(1).is_some_and(|c| c.is_ascii_alphabetic() || c == '_') {
            return 1 + run(text, 1, word); // a lifetime
        }
        return 1;
    }
    let is_hex = |c: char| c.is_ascii_hexdigit() || c == '_';
    if first == '0' && matches!(at(1), Some('x' | 'X')) && at(2).is_some_and(is_hex) {
        return 2 + run(text, 2, word);
    }
    if digit(first) || (first == '.' && at(1).is_some_and(digit)) {
        let mut k = 1 + run(text, 1, |c| digit(c) || c == '_');
        if first == '.' {
            k = 1 + run(text, 1, digit);
        } else if at(k) == Some('.') && at(k + 1).is_some_and(digit) {
            k += 1 + run(text, k + 1, |c| digit(c) || c == '_');
        }
        k += exponent(text, k);
        return k + run(text, k, word);
    }
    if first.is_ascii_alphabetic() || first == '_' {
        return run(text, 0, word);
    }
    for operator in OPERATORS {
        if operator.chars().enumerate().all(|(k, c)| at(k) == Some(c)) {
            return operator.len();
        }
    }
    1
}

pub fn count_tokens(code: &str) -> usize {
    let chars: Vec<char> = code.chars().collect();
    let mut tokens = 0;
    let mut i = 0;
    while i < chars.len() {
        if chars[i].is_whitespace() {
            i += 1;
        } else {
            i += token_length(&chars[i..]);
            tokens += 1;
        }
    }
    tokens
}

pub fn non_blank_lines(source: &str) -> usize {
    source
        .lines()
        .filter(|line| !line.trim().is_empty())
        .count()
}
