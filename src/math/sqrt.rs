//! Integer square root: the only root the pipeline takes (normals, light directions, camera
//! axes), exact and free of floats.

/// `floor(sqrt(n))`, bit by bit: 32 iterations of shifts, adds and compares, no division.
pub(crate) const fn isqrt_u64(n: u64) -> u64 {
    let mut rem = n;
    let mut root = 0u64;
    let mut bit = 1u64 << 62;
    while bit > n {
        bit >>= 2;
    }
    while bit != 0 {
        if rem >= root + bit {
            rem -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    root
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn isqrt_is_exact_floor() {
        for n in (0u64..20_000).chain([u64::MAX, u64::MAX - 1, 1 << 62, (1 << 62) - 1]) {
            let r = isqrt_u64(n) as u128;
            assert!(
                r * r <= n as u128 && (r + 1) * (r + 1) > n as u128,
                "n = {n}"
            );
        }
        let mut x = 0x9E37_79B9_7F4A_7C15u64;
        for _ in 0..10_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let r = isqrt_u64(x) as u128;
            assert!(r * r <= x as u128 && (r + 1) * (r + 1) > x as u128);
        }
    }
}
