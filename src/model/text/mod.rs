//! Field values from their text: the number scanners, the value grammar of the XML and
//! ClassicVRML encodings, and the cutting of long numeric values into pieces parsed on
//! several threads. They sit in the model rather than with the readers because the model
//! itself parses text: the schema's defaults, written in the XML encoding. The readers
//! (`crate::parse`) use them from here.

pub mod huge_vec;
pub mod number;
pub mod split;
pub mod xml_value;
