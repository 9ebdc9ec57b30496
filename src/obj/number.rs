//! Decimal numbers straight into fixed point, correctly rounded, in a `const fn` (so meshes can
//! be parsed at compile time). No float is involved: `inf`, `nan` and out-of-range values are
//! errors, never a wrapped or saturated coordinate.

/// What is wrong with a number.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum NumberError {
    /// Not a decimal number (`1,5`, `1.0.0`, `0x10`, `1e`, `--1`, `1_0`, a non-ASCII digit…).
    Invalid,
    /// `inf`, `infinity` or `nan`, in any case and with any sign.
    NotFinite,
    /// Finite but outside the representable range.
    OutOfRange,
}

/// Fraction digits kept exactly (10¹⁹ < 2⁶⁴); any further non-zero digit only sets a sticky
/// flag. Every tie point of a 16-bit binary fraction has at most 16 decimals, so this rounds
/// correctly however long the mantissa.
const KEPT: u32 = 19;
const TEN_POW_KEPT: u64 = 10_000_000_000_000_000_000;

const fn lower(b: u8) -> u8 {
    b.to_ascii_lowercase()
}

/// True when `s` (without sign) spells inf, infinity or nan, in any case.
const fn is_non_finite_word(s: &[u8], start: usize) -> bool {
    let n = s.len() - start;
    let word: &[&[u8]] = &[b"inf", b"infinity", b"nan"];
    let mut w = 0;
    while w < word.len() {
        let cand = word[w];
        if cand.len() == n {
            let mut i = 0;
            while i < n && lower(s[start + i]) == cand[i] {
                i += 1;
            }
            if i == n {
                return true;
            }
        }
        w += 1;
    }
    false
}

/// Parses `[+-](digits[.digits*] | .digits)[(e|E)[+-]digits]` into a fixed-point value with
/// `frac_bits` fraction bits (16 for Q16.16) whose magnitude is at most `max_raw` (`max_raw + 1`
/// for negative values), rounding to nearest with ties to even.
pub(crate) const fn parse_fixed(
    s: &[u8],
    frac_bits: u32,
    max_raw: u64,
) -> Result<i64, NumberError> {
    let len = s.len();
    let mut i = 0;
    let mut negative = false;
    if i < len && (s[i] == b'+' || s[i] == b'-') {
        negative = s[i] == b'-';
        i += 1;
    }
    if i < len && (lower(s[i]) == b'i' || lower(s[i]) == b'n') {
        return Err(if is_non_finite_word(s, i) {
            NumberError::NotFinite
        } else {
            NumberError::Invalid
        });
    }
    // Pass 1: the grammar, the digits before the point and the exponent.
    let mant_start = i;
    let mut int_digits: i64 = 0;
    let mut digits = 0;
    let mut seen_point = false;
    while i < len {
        let b = s[i];
        if b.is_ascii_digit() {
            digits += 1;
            if !seen_point {
                int_digits += 1;
            }
        } else if b == b'.' && !seen_point {
            seen_point = true;
        } else {
            break;
        }
        i += 1;
    }
    let mant_end = i;
    if digits == 0 {
        return Err(NumberError::Invalid);
    }
    let mut exp: i64 = 0;
    if i < len && (s[i] == b'e' || s[i] == b'E') {
        i += 1;
        let mut exp_negative = false;
        if i < len && (s[i] == b'+' || s[i] == b'-') {
            exp_negative = s[i] == b'-';
            i += 1;
        }
        let exp_start = i;
        while i < len && s[i].is_ascii_digit() {
            if exp < 1_000_000 {
                exp = exp * 10 + (s[i] - b'0') as i64;
            }
            i += 1;
        }
        if i == exp_start {
            return Err(NumberError::Invalid);
        }
        if exp_negative {
            exp = -exp;
        }
    }
    if i != len {
        return Err(NumberError::Invalid);
    }
    // Pass 2: every digit at its decimal position p (weight 10^p).
    let limit = (max_raw >> frac_bits) + 1; // an integer part above this is out of range
    let mut int_part: u64 = 0;
    let mut frac: u64 = 0; // the first KEPT fraction digits, scaled by 10^KEPT
    let mut sticky = false;
    let mut k: i64 = 0;
    let mut last_p: i64 = 0;
    let mut j = mant_start;
    while j < mant_end {
        let b = s[j];
        j += 1;
        if b == b'.' {
            continue;
        }
        let d = (b - b'0') as u64;
        let p = int_digits - 1 - k + exp;
        k += 1;
        last_p = p;
        if p >= 0 {
            if int_part > limit {
                return Err(NumberError::OutOfRange);
            }
            int_part = int_part * 10 + d;
        } else if -p <= KEPT as i64 {
            let mut w = TEN_POW_KEPT;
            let mut q = 0;
            while q < -p {
                w /= 10;
                q += 1;
            }
            frac += d * w;
        } else if d != 0 {
            sticky = true;
        }
    }
    // Digits ended above the units: scale the integer part up.
    let mut p = last_p;
    while p > 0 {
        if int_part > limit {
            return Err(NumberError::OutOfRange);
        }
        int_part *= 10;
        p -= 1;
    }
    if int_part > limit {
        return Err(NumberError::OutOfRange);
    }
    let scaled = (frac as u128) << frac_bits;
    let mut q = (scaled / TEN_POW_KEPT as u128) as u64;
    let r = (scaled % TEN_POW_KEPT as u128) as u64;
    let half = TEN_POW_KEPT / 2;
    if r > half || (r == half && (sticky || q & 1 == 1)) {
        q += 1;
    }
    let raw = (int_part << frac_bits) + q;
    let max = if negative { max_raw + 1 } else { max_raw };
    if raw > max {
        return Err(NumberError::OutOfRange);
    }
    Ok(if negative { -(raw as i64) } else { raw as i64 })
}

/// A Q16.16 coordinate (raw bits).
pub(crate) const fn parse_q16(s: &[u8]) -> Result<i32, NumberError> {
    match parse_fixed(s, 16, i32::MAX as u64) {
        Ok(v) => Ok(v as i32),
        Err(e) => Err(e),
    }
}

/// A Q32.16 coordinate (raw bits, range ±2³¹), for files to be rescaled into Q16.16.
pub(crate) const fn parse_wide(s: &[u8]) -> Result<i64, NumberError> {
    parse_fixed(s, 16, (1u64 << 47) - 1)
}

/// An OBJ index: `[+-]digits`, any magnitude that fits i64 (larger is out of range).
pub(crate) const fn parse_index(s: &[u8]) -> Result<i64, NumberError> {
    let len = s.len();
    let mut i = 0;
    let mut negative = false;
    if i < len && (s[i] == b'+' || s[i] == b'-') {
        negative = s[i] == b'-';
        i += 1;
    }
    if i == len {
        return Err(NumberError::Invalid);
    }
    let mut v: i64 = 0;
    while i < len {
        let b = s[i];
        if !b.is_ascii_digit() {
            return Err(NumberError::Invalid);
        }
        v = match v.checked_mul(10) {
            Some(x) => match x.checked_add((b - b'0') as i64) {
                Some(y) => y,
                None => return Err(NumberError::OutOfRange),
            },
            None => return Err(NumberError::OutOfRange),
        };
        i += 1;
    }
    Ok(if negative { -v } else { v })
}

#[cfg(test)]
mod tests {
    use super::*;
    extern crate std;
    use std::format;

    fn q(s: &str) -> Result<i32, NumberError> {
        parse_q16(s.as_bytes())
    }

    /// The correctly rounded Q16.16 value of a short decimal, computed in f64 (exact for these).
    fn expect(v: f64) -> i32 {
        let x = v * 65536.0;
        let r = x.round();
        // ties to even
        let r = if (x - x.trunc()).abs() == 0.5 {
            2.0 * (x / 2.0).round()
        } else {
            r
        };
        r as i32
    }

    #[test]
    fn valid_forms() {
        assert_eq!(q("1"), Ok(1 << 16));
        assert_eq!(q("-2.5"), Ok(-(5 << 15)));
        assert_eq!(q("+1.0"), Ok(1 << 16));
        assert_eq!(q("-.5"), Ok(-(1 << 15)));
        assert_eq!(q("1."), Ok(1 << 16));
        assert_eq!(q("1e-3"), Ok(expect(1e-3)));
        assert_eq!(q("1.0E2"), Ok(100 << 16));
        assert_eq!(q("0.0000076"), Ok(0));
        assert_eq!(q("-0"), Ok(0));
        assert_eq!(q("-0.0"), Ok(0));
        assert_eq!(q("32767.99998"), Ok(i32::MAX));
        assert_eq!(q("-32768"), Ok(i32::MIN));
        assert_eq!(q("0.00000762939453125"), Ok(0)); // exactly half an LSB: ties to even
        assert_eq!(q("0.00002288818359375"), Ok(2)); // 1.5 LSB: ties to even
        assert_eq!(q("0.000007629394531250001"), Ok(1)); // just above half
        assert_eq!(q("123e-2"), Ok(expect(1.23)));
        assert_eq!(q("0.000000000000000000000000001e27"), Ok(1 << 16));
        assert_eq!(q("0e99999999999"), Ok(0));
        assert_eq!(q("5e-99999999999"), Ok(0));
    }

    #[test]
    fn o9_long_mantissa_is_correctly_rounded() {
        let s = "0.123456789012345678901234567890123456789012345678901234567890";
        assert_eq!(q(s), Ok(expect(0.123_456_789_012_345_68)));
    }

    #[test]
    fn o4_o5_o7_errors() {
        for s in ["inf", "-inf", "nan", "NaN", "-nan", "Infinity", "INF"] {
            assert_eq!(q(s), Err(NumberError::NotFinite), "{s}");
        }
        // O5: 32767.99999 lies within half a step of the largest Q16.16 value and rounds to it
        // (a float parse would round it to 32768 first and reject it); 32767.999993 does not.
        assert_eq!(q("32767.99999"), Ok(i32::MAX));
        for s in [
            "1e40",
            "40000",
            "32768",
            "32767.999993",
            "-32768.00001",
            "1e5",
            "99999999999999999999999",
        ] {
            assert_eq!(q(s), Err(NumberError::OutOfRange), "{s}");
        }
        for s in [
            "1,5", "1.0.0", "0x10", "1e", "--1", "1_0", "١", "", ".", "+", "e5", "1e+", "i",
            "info", "1 2", "1.5f",
        ] {
            assert_eq!(q(s), Err(NumberError::Invalid), "{s}");
        }
    }

    #[test]
    fn random_decimals_round_like_f64() {
        let mut rng = crate::testing::XorShift(0x1234_5678_9abc_def0u64);
        for _ in 0..20_000 {
            let x = rng.next_u64();
            let v = ((x >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 60000.0;
            let s = format!("{v:.6}");
            let exact: f64 = s.parse().unwrap_or(0.0);
            let got = q(&s).unwrap_or(0) as f64;
            assert!((got - exact * 65536.0).abs() <= 0.5 + 1e-6, "{s}");
        }
    }

    #[test]
    fn indices() {
        assert_eq!(parse_index(b"+3"), Ok(3));
        assert_eq!(parse_index(b"-2147483648"), Ok(-2_147_483_648));
        assert_eq!(
            parse_index(b"99999999999999999999"),
            Err(NumberError::OutOfRange)
        );
        assert_eq!(parse_index(b""), Err(NumberError::Invalid));
        assert_eq!(parse_index(b"1.5"), Err(NumberError::Invalid));
        assert_eq!(parse_wide(b"40000"), Ok(40000 << 16));
    }
}
