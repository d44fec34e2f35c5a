//! The getters and setters of the FMI 3 types the FMU has variables of under their C names, for
//! [`crate::export_fmi3!`]: Float64, Int32, Int64, Boolean and String, forwarding to the generic
//! functions.

/// Part of [`crate::export_fmi3!`], which invokes it.
#[doc(hidden)]
#[macro_export]
macro_rules! export_fmi3_values {
    ($model:ty) => {
        $crate::forward_export!(fmi3, $model;
            fmi3GetFloat64: fmi3GetFloat64TYPE, (instance: fmi3Instance,
                valueReferences: *const fmi3ValueReference, nValueReferences: usize,
                values: *mut fmi3Float64, nValues: usize) -> fmi3Status;
            fmi3GetInt32: fmi3GetInt32TYPE, (instance: fmi3Instance,
                valueReferences: *const fmi3ValueReference, nValueReferences: usize,
                values: *mut fmi3Int32, nValues: usize) -> fmi3Status;
            fmi3GetInt64: fmi3GetInt64TYPE, (instance: fmi3Instance,
                valueReferences: *const fmi3ValueReference, nValueReferences: usize,
                values: *mut fmi3Int64, nValues: usize) -> fmi3Status;
            fmi3GetBoolean: fmi3GetBooleanTYPE, (instance: fmi3Instance,
                valueReferences: *const fmi3ValueReference, nValueReferences: usize,
                values: *mut fmi3Boolean, nValues: usize) -> fmi3Status;
            fmi3GetString: fmi3GetStringTYPE, (instance: fmi3Instance,
                valueReferences: *const fmi3ValueReference, nValueReferences: usize,
                values: *mut fmi3String, nValues: usize) -> fmi3Status;
            fmi3SetFloat64: fmi3SetFloat64TYPE, (instance: fmi3Instance,
                valueReferences: *const fmi3ValueReference, nValueReferences: usize,
                values: *const fmi3Float64, nValues: usize) -> fmi3Status;
            fmi3SetInt32: fmi3SetInt32TYPE, (instance: fmi3Instance,
                valueReferences: *const fmi3ValueReference, nValueReferences: usize,
                values: *const fmi3Int32, nValues: usize) -> fmi3Status;
            fmi3SetInt64: fmi3SetInt64TYPE, (instance: fmi3Instance,
                valueReferences: *const fmi3ValueReference, nValueReferences: usize,
                values: *const fmi3Int64, nValues: usize) -> fmi3Status;
            fmi3SetBoolean: fmi3SetBooleanTYPE, (instance: fmi3Instance,
                valueReferences: *const fmi3ValueReference, nValueReferences: usize,
                values: *const fmi3Boolean, nValues: usize) -> fmi3Status;
            fmi3SetString: fmi3SetStringTYPE, (instance: fmi3Instance,
                valueReferences: *const fmi3ValueReference, nValueReferences: usize,
                values: *const fmi3String, nValues: usize) -> fmi3Status;
        );
    };
}
