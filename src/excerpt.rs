//! Bounded quotations of user input in messages: an error quotes at most [`MAX_QUOTE`] bytes of
//! each piece of input, and says at most [`MAX_MESSAGE`] bytes, so a value of 10 kB (5000
//! nested parentheses) gets a short message. Bounding a bounded message changes nothing.

use std::borrow::Cow;

/// Bytes of one quoted piece of input an error message shows, ellipsis included.
pub const MAX_QUOTE: usize = 80;

/// Bytes of a whole message, whatever it quotes.
pub const MAX_MESSAGE: usize = 512;

/// The longest prefix of `s` within `max` bytes that ends on a character boundary.
fn head(s: &str, max: usize) -> &str {
    let mut end = max.min(s.len());
    while !s.is_char_boundary(end) {
        end -= 1;
    }
    &s[..end]
}

/// `s` itself when it is at most [`MAX_QUOTE`] bytes; otherwise its beginning (cut on a
/// character boundary), an ellipsis and its length in characters, [`MAX_QUOTE`] bytes in all.
///
/// ```
/// use torseur::excerpt::excerpt;
/// assert_eq!(excerpt("m2*L1"), "m2*L1");
/// let nested = format!("{}m1{}", "(".repeat(5000), ")".repeat(5000));
/// assert_eq!(excerpt(&nested), format!("{}… (10002 characters)", "(".repeat(58)));
/// let long = "é".repeat(100);
/// let accents = excerpt(&long);
/// assert_eq!(accents, format!("{}… (100 characters)", "é".repeat(30)));
/// assert_eq!(excerpt(&accents), accents);
/// ```
pub fn excerpt(s: &str) -> Cow<'_, str> {
    if s.len() <= MAX_QUOTE {
        return Cow::Borrowed(s);
    }
    let tail = format!("… ({} characters)", s.chars().count());
    Cow::Owned(format!("{}{tail}", head(s, MAX_QUOTE - tail.len())))
}

/// A message with every quoted piece (between backticks or double quotes) cut to an
/// [`excerpt`], then the whole cut to [`MAX_MESSAGE`] bytes: for messages that quote input
/// they do not control (serde's, a nested error's).
///
/// ```
/// use torseur::excerpt::bounded;
/// assert_eq!(bounded("unknown frame `9`"), "unknown frame `9`");
/// let long = format!("unknown frame `{}`, expected a frame", "x".repeat(10_000));
/// let b = bounded(&long);
/// assert!(b.len() < 120 && b.ends_with("`, expected a frame"), "{b}");
/// assert_eq!(bounded(&b), b);
/// // Many short quotes: the whole is cut.
/// let many = "`a` ".repeat(5000);
/// assert!(bounded(&many).len() <= torseur::excerpt::MAX_MESSAGE);
/// ```
pub fn bounded(message: &str) -> Cow<'_, str> {
    if message.len() <= MAX_QUOTE {
        return Cow::Borrowed(message);
    }
    let mut out = String::new();
    let mut rest = message;
    while let Some(open) = rest.find(['`', '"']) {
        let quote = rest[open..].chars().next().unwrap_or('`');
        let inner = &rest[open + 1..];
        let Some(close) = inner.find(quote) else {
            break;
        };
        out.push_str(&rest[..=open]);
        out.push_str(&excerpt(&inner[..close]));
        out.push(quote);
        rest = &inner[close + 1..];
    }
    out.push_str(rest);
    if out.len() > MAX_MESSAGE {
        let cut = head(&out, MAX_MESSAGE - '…'.len_utf8()).len();
        out.truncate(cut);
        out.push('…');
    }
    if out == message {
        Cow::Borrowed(message)
    } else {
        Cow::Owned(out)
    }
}
