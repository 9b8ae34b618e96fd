//! Dispatch over a registry's FMUs, naming none: each macro takes the list of FMU types [`super::exports!`]
//! was given and runs its body with `$M` the chosen one.

/// `$body` with `$M` the FMU whose instance tag `$tag` (an `Option<u64>`) is; the last FMU when none is
/// (its body then refuses the pointer).
macro_rules! by_tag {
    ([$last:ty] $tag:expr, $M:ident => $body:expr) => {{
        type $M = $last;
        $body
    }};
    ([$first:ty, $($rest:ty),+] $tag:expr, $M:ident => $body:expr) => {
        if $tag == Some(<$first as $crate::fmi::Model>::INSTANCE_TAG) {
            type $M = $first;
            $body
        } else {
            $crate::fmi::registry::by_tag!([$($rest),+] $tag, $M => $body)
        }
    };
}
pub(crate) use by_tag;

/// `$body` with `$M` the FMU fmi2Instantiate makes: the one whose name the binary is stamped with
/// (`$stamp: Option<&str>`), or, unstamped, the first whose GUID is `$guid` (an `unsafe` C string read);
/// the last FMU when none claims it (its own checks then refuse the GUID).
macro_rules! by_identity {
    ([$last:ty] $stamp:expr, $guid:expr, $M:ident => $body:expr) => {{
        type $M = $last;
        $body
    }};
    ([$first:ty, $($rest:ty),+] $stamp:expr, $guid:expr, $M:ident => $body:expr) => {{
        type First = $first;
        let claims = match $stamp {
            Some(name) => name == <First as $crate::fmi::Model>::NAME,
            None => $crate::fmi::functions::has_guid::<First>($guid),
        };
        if claims {
            type $M = First;
            $body
        } else {
            $crate::fmi::registry::by_identity!([$($rest),+] $stamp, $guid, $M => $body)
        }
    }};
}
pub(crate) use by_identity;
