//! The getters and setters of the FMI 3 types the FMU has variables of under their C names, for
//! [`crate::export_fmi3!`]: Float64, Int32, Int64, Boolean and String, forwarding to the generic
//! functions.

/// Part of [`crate::export_fmi3!`], which invokes it.
#[doc(hidden)]
#[macro_export]
macro_rules! export_fmi3_values {
    ($model:ty) => {
        $crate::forward_export!(
            fmi3, $model,
            fmi3GetFloat64: fmi3GetFloat64TYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *mut $crate::fmi3::exports::sys::fmi3Float64,
            nValues: usize,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3GetInt32: fmi3GetInt32TYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *mut $crate::fmi3::exports::sys::fmi3Int32,
            nValues: usize,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3GetInt64: fmi3GetInt64TYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *mut $crate::fmi3::exports::sys::fmi3Int64,
            nValues: usize,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3GetBoolean: fmi3GetBooleanTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            nValues: usize,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3GetString: fmi3GetStringTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *mut $crate::fmi3::exports::sys::fmi3String,
            nValues: usize,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3SetFloat64: fmi3SetFloat64TYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *const $crate::fmi3::exports::sys::fmi3Float64,
            nValues: usize,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3SetInt32: fmi3SetInt32TYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *const $crate::fmi3::exports::sys::fmi3Int32,
            nValues: usize,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3SetInt64: fmi3SetInt64TYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *const $crate::fmi3::exports::sys::fmi3Int64,
            nValues: usize,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3SetBoolean: fmi3SetBooleanTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *const $crate::fmi3::exports::sys::fmi3Boolean,
            nValues: usize,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3SetString: fmi3SetStringTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *const $crate::fmi3::exports::sys::fmi3String,
            nValues: usize,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
    };
}
