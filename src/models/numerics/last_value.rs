//! A pure function's value at the last argument it was asked for. RK4's two half-step stages
//! share a time, and so do a step's last stage and its end sample: where the terms of a time are
//! costly (the crank's sine, cosine and pressure; the roller's Λ), the second of a pair reuses them.
//! A communication point's drive torque likewise reuses the crank row of the point's evaluation.

use std::cell::Cell;

/// A cache, not state: not saved, equal in every comparison, and never changing a result (it
/// hands back exactly what the function gave for the same argument, bit for bit). The argument
/// is `K` numbers.
#[derive(Clone, Debug)]
pub(crate) struct LastValue<T: Copy, const K: usize = 1>(Cell<Option<([f64; K], T)>>);

impl<T: Copy, const K: usize> LastValue<T, K> {
    /// `compute()`'s value at `args`, from the cache when `args` are the last arguments, bit for
    /// bit. Inlined: a hit must cost a comparison, not a call.
    #[inline(always)]
    pub fn get_or(&self, args: [f64; K], compute: impl FnOnce() -> T) -> T {
        match self.0.get() {
            Some((last, value)) if (0..K).all(|k| last[k].to_bits() == args[k].to_bits()) => value,
            _ => {
                let value = compute();
                self.set(args, value);
                value
            }
        }
    }

    /// Takes `value`, the function's at `args`, as the last one.
    pub fn set(&self, args: [f64; K], value: T) {
        self.0.set(Some((args, value)));
    }
}

impl<T: Copy, const K: usize> Default for LastValue<T, K> {
    fn default() -> Self {
        Self(Cell::new(None))
    }
}

impl<T: Copy, const K: usize> PartialEq for LastValue<T, K> {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn computes_once_per_repeated_argument_and_again_for_any_other_bit_pattern() {
        let (cache, calls) = (LastValue::default(), Cell::new(0));
        let value = |x: f64| {
            calls.set(calls.get() + 1);
            libm::sin(x)
        };
        for (arg, computed) in [(0.5, 1), (0.5, 1), (0.25, 2), (0.5, 3), (0.0, 4), (-0.0, 5), (-0.0, 5)] {
            let got = cache.get_or([arg], || value(arg));
            assert_eq!(got.to_bits(), libm::sin(arg).to_bits(), "{arg}");
            assert_eq!(calls.get(), computed, "calls after {arg}");
        }
    }
}
