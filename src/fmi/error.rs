//! What a model answers the FMI layer when it refuses or fails: a refused parameter set, a failed step, a
//! state it cannot take back. The layer logs the message and returns fmi2Error.

use std::fmt;

/// A refusal or failure, with a message naming the cause.
#[derive(Clone, Debug, PartialEq)]
pub struct Error(pub String);

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

/// Any error of a model, by its message.
impl<E: std::error::Error> From<E> for Error {
    fn from(e: E) -> Self {
        Self(e.to_string())
    }
}
