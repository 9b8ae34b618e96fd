//! The host's pointers as Rust values: arrays, out-parameters, strings. A NULL where data is needed is
//! refused, never read.
#![allow(unsafe_code)]

use super::instance::{Outcome, Refusal};
use super::types::fmi2String;
use std::ffi::CStr;

/// The `n` elements at `ptr`; NULL is refused unless `n` is 0.
///
/// # Safety
/// A non-NULL `ptr` points to `n` initialized elements that stay valid and unaliased for `'a`.
pub unsafe fn slice<'a, T>(ptr: *const T, n: usize, what: &str) -> Outcome<&'a [T]> {
    if n == 0 {
        return Ok(&[]);
    }
    if ptr.is_null() || n > isize::MAX as usize / std::mem::size_of::<T>().max(1) {
        return Err(Refusal::error(format!("{what} is NULL (or its length {n} impossible)")));
    }
    // SAFETY: non-NULL, the length fits an allocation, and the caller vouches for the memory.
    Ok(unsafe { std::slice::from_raw_parts(ptr, n) })
}

/// As [`slice`], writable.
///
/// # Safety
/// As [`slice`], and no other reference to the elements exists for `'a`.
pub unsafe fn slice_mut<'a, T>(ptr: *mut T, n: usize, what: &str) -> Outcome<&'a mut [T]> {
    // SAFETY: the same contract; this only checks the pointer and the length.
    unsafe { slice(ptr as *const T, n, what)? };
    if n == 0 {
        return Ok(&mut []);
    }
    // SAFETY: checked non-NULL and of a possible length by `slice`; exclusive by the contract.
    Ok(unsafe { std::slice::from_raw_parts_mut(ptr, n) })
}

/// The out-parameter at `ptr`.
///
/// # Safety
/// A non-NULL `ptr` points to a writable `T`, not aliased for `'a`.
pub unsafe fn out<'a, T>(ptr: *mut T, what: &str) -> Outcome<&'a mut T> {
    // SAFETY: `as_mut` checks for NULL; validity is the caller's contract.
    unsafe { ptr.as_mut() }.ok_or_else(|| Refusal::error(format!("{what} is NULL")))
}

/// The UTF-8 string at `s`.
///
/// # Safety
/// A non-NULL `s` points to a NUL-terminated string valid for `'a`.
pub unsafe fn string<'a>(s: fmi2String, what: &str) -> Outcome<&'a str> {
    if s.is_null() {
        return Err(Refusal::error(format!("{what} is NULL")));
    }
    // SAFETY: non-NULL and NUL-terminated by the contract.
    unsafe { CStr::from_ptr(s) }.to_str().map_err(|_| Refusal::error(format!("{what} is not UTF-8")))
}
