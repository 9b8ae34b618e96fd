//! Dispatch over the registered FMUs (`crate::fmus::registry!`), naming none: each macro takes the registry's
//! list of rooms and runs its body with `$M` the chosen room's `Fmu` type.

/// `$body` with `$M` the FMU whose instance tag `$tag` (an `Option<u64>`) is; the last FMU when none is
/// (its body then refuses the pointer).
macro_rules! by_tag {
    ([$last:ident] $tag:expr, $M:ident => $body:expr) => {{
        type $M = crate::fmus::$last::Fmu;
        $body
    }};
    ([$first:ident, $($rest:ident),+] $tag:expr, $M:ident => $body:expr) => {
        if $tag == Some(<crate::fmus::$first::Fmu as crate::fmi::Model>::INSTANCE_TAG) {
            type $M = crate::fmus::$first::Fmu;
            $body
        } else {
            by_tag!([$($rest),+] $tag, $M => $body)
        }
    };
}
pub(crate) use by_tag;

/// `$body` with `$M` the FMU fmi2Instantiate makes: the one whose name the binary is stamped with
/// (`$stamp: Option<&str>`), or, unstamped, the first whose GUID is `$guid` (an `unsafe` C string read);
/// the last FMU when none claims it (its own checks then refuse the GUID).
macro_rules! by_identity {
    ([$last:ident] $stamp:expr, $guid:expr, $M:ident => $body:expr) => {{
        type $M = crate::fmus::$last::Fmu;
        $body
    }};
    ([$first:ident, $($rest:ident),+] $stamp:expr, $guid:expr, $M:ident => $body:expr) => {{
        type First = crate::fmus::$first::Fmu;
        let claims = match $stamp {
            Some(name) => name == <First as crate::fmi::Model>::NAME,
            None => functions::has_guid::<First>($guid),
        };
        if claims {
            type $M = First;
            $body
        } else {
            by_identity!([$($rest),+] $stamp, $guid, $M => $body)
        }
    }};
}
pub(crate) use by_identity;
