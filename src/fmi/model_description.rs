//! The FMU's identity: its model identifier, and the modelDescription.xml and GUID that
//! `build.rs` renders from the variable table.

fmi_export::model_identity!(crate::variables::DESCRIPTION);
