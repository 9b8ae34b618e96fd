//! Calls back into an instance from inside one of its own calls. The host's logger runs inside the
//! call that logs; if it calls another instance, that is fine, but a call into the same instance
//! would run on the state the outer call is changing, or free it from under it. Such a call is
//! refused. Simultaneous calls from other threads are the host's to avoid: FMI 2.0 does not
//! require one instance to be thread safe.

use std::cell::Cell;

/// Instances with a call in progress that one thread can nest (a logger calling another instance,
/// whose logger calls a third...); a deeper nesting is refused too.
const DEPTH: usize = 8;

/// The addresses of the instances with a call in progress on this thread, innermost last.
struct Active {
    depth: Cell<usize>,
    addresses: [Cell<usize>; DEPTH],
}

thread_local! {
    static ACTIVE: Active = const { Active { depth: Cell::new(0), addresses: [const { Cell::new(0) }; DEPTH] } };
}

/// A call in progress on one instance; dropping it ends the call.
pub struct Entered(());

impl Entered {
    /// Enters a call on the instance at `address`; `None` if one is already in progress on it.
    pub fn new(address: usize) -> Option<Self> {
        ACTIVE.with(|active| {
            let depth = active.depth.get();
            if depth == DEPTH || active.addresses[..depth].iter().any(|a| a.get() == address) {
                return None;
            }
            active.addresses[depth].set(address);
            active.depth.set(depth + 1);
            Some(Self(()))
        })
    }
}

impl Drop for Entered {
    fn drop(&mut self) {
        ACTIVE.with(|active| active.depth.set(active.depth.get() - 1));
    }
}
