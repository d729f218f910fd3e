//! Machinery a student need not read: a small pseudo-random generator (xorshift64*, Vigna 2016)
//! for the tests that try many poses and rays, seeded so that a failure can be replayed.
use glam::{DVec3, dvec3};

pub struct Random {
    state: u64,
}

impl Random {
    pub fn new(seed: u64) -> Random {
        // Multiplying by 2^64 / φ (the golden ratio) spreads neighbouring seeds over all 64 bits;
        // the lowest bit set keeps the state off 0, where xorshift would stay for ever.
        Random {
            state: seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1,
        }
    }
    /// A number from 0 up to 1, never 1 itself.
    pub fn next(&mut self) -> f64 {
        // xorshift64*'s published shifts (12, 25, 27) and multiplier (Vigna, 2016).
        self.state ^= self.state >> 12;
        self.state ^= self.state << 25;
        self.state ^= self.state >> 27;
        let bits = self.state.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11; // the top 53 bits
        bits as f64 / (1u64 << 53) as f64
    }
    /// A number from `low` up to `high`.
    pub fn between(&mut self, low: f64, high: f64) -> f64 {
        low + (high - low) * self.next()
    }
    /// One of the items, each as likely.
    pub fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[(self.next() * items.len() as f64) as usize]
    }
    /// A point in the cube from -size to size on each axis.
    pub fn point(&mut self, size: f64) -> DVec3 {
        dvec3(
            self.between(-size, size),
            self.between(-size, size),
            self.between(-size, size),
        )
    }
}
