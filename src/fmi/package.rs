//! What the packer (`src/bin/package_fmu.rs`) needs of an FMU besides its binaries. Safe code.

use super::description::Variable;

/// An FMU's archive contents apart from `binaries/`.
pub struct Package {
    /// The model identifier: the archive's name and the binaries' file name.
    pub name: &'static str,
    /// The generated FMI 2.0 `modelDescription.xml`.
    pub model_description_xml: &'static str,
    /// The generated FMI 3.0 `modelDescription.xml` of the FMI 3.0 FMU.
    pub fmi3_model_description_xml: &'static str,
    /// The variable table the documentation lists.
    pub variables: &'static [Variable],
    /// `documentation/index.html` with the placeholders `{{version}}` and `{{variables}}`.
    pub documentation: &'static str,
    /// Further files: (path in the archive, bytes).
    pub files: &'static [(&'static str, &'static [u8])],
}
