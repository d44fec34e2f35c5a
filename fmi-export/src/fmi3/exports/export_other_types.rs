//! The getters and setters of the FMI 3 types beyond the table's, under their C names, for
//! [`crate::export_fmi3!`]: UInt64, the structural parameters' type, forwards to the layer; those
//! of the types the FMU has no variable of (Float32, the small integers, Binary, Clock) refuse
//! every value reference, naming its variable.

/// Part of [`crate::export_fmi3!`], which invokes it.
#[doc(hidden)]
#[macro_export]
macro_rules! export_fmi3_other_types {
    ($model:ty) => {
        $crate::fmi3_no_variable_of_type!($model;
            fmi3GetFloat32: fmi3GetFloat32TYPE, "Float32", _values: *mut fmi3Float32,
                _nValues: usize;
            fmi3GetInt8: fmi3GetInt8TYPE, "Int8", _values: *mut fmi3Int8, _nValues: usize;
            fmi3GetUInt8: fmi3GetUInt8TYPE, "UInt8", _values: *mut fmi3UInt8, _nValues: usize;
            fmi3GetInt16: fmi3GetInt16TYPE, "Int16", _values: *mut fmi3Int16, _nValues: usize;
            fmi3GetUInt16: fmi3GetUInt16TYPE, "UInt16", _values: *mut fmi3UInt16, _nValues: usize;
            fmi3GetUInt32: fmi3GetUInt32TYPE, "UInt32", _values: *mut fmi3UInt32, _nValues: usize;
        );
        $crate::forward_export!(fmi3, $model;
            fmi3GetUInt64: fmi3GetUInt64TYPE, (instance: fmi3Instance,
                valueReferences: *const fmi3ValueReference, nValueReferences: usize,
                values: *mut fmi3UInt64, nValues: usize) -> fmi3Status;
        );
        $crate::fmi3_no_variable_of_type!($model;
            fmi3GetBinary: fmi3GetBinaryTYPE, "Binary", _valueSizes: *mut usize,
                _values: *mut fmi3Binary, _nValues: usize;
            fmi3GetClock: fmi3GetClockTYPE, "Clock", _values: *mut fmi3Clock;
            fmi3SetFloat32: fmi3SetFloat32TYPE, "Float32", _values: *const fmi3Float32,
                _nValues: usize;
            fmi3SetInt8: fmi3SetInt8TYPE, "Int8", _values: *const fmi3Int8, _nValues: usize;
            fmi3SetUInt8: fmi3SetUInt8TYPE, "UInt8", _values: *const fmi3UInt8, _nValues: usize;
            fmi3SetInt16: fmi3SetInt16TYPE, "Int16", _values: *const fmi3Int16, _nValues: usize;
            fmi3SetUInt16: fmi3SetUInt16TYPE, "UInt16", _values: *const fmi3UInt16,
                _nValues: usize;
            fmi3SetUInt32: fmi3SetUInt32TYPE, "UInt32", _values: *const fmi3UInt32,
                _nValues: usize;
        );
        $crate::forward_export!(fmi3, $model;
            fmi3SetUInt64: fmi3SetUInt64TYPE, (instance: fmi3Instance,
                valueReferences: *const fmi3ValueReference, nValueReferences: usize,
                values: *const fmi3UInt64, nValues: usize) -> fmi3Status;
        );
        $crate::fmi3_no_variable_of_type!($model;
            fmi3SetBinary: fmi3SetBinaryTYPE, "Binary", _valueSizes: *const usize,
                _values: *const fmi3Binary, _nValues: usize;
            fmi3SetClock: fmi3SetClockTYPE, "Clock", _values: *const fmi3Clock;
        );
    };
}

/// `fmi3Get*`/`fmi3Set*` functions of types the FMU has no variable of, for
/// [`crate::export_fmi3_other_types!`]: each `$name` under its C name with the arguments after the
/// value references (`$arg: $ty`, of the header's types, unused), its signature pinned to the
/// header's `$pinned`; it refuses every value reference ([`crate::fmi3::exports::no_variable_of_type`]).
#[doc(hidden)]
#[macro_export]
macro_rules! fmi3_no_variable_of_type {
    ($model:ty; $($name:ident: $pinned:ident, $type_name:literal $(, $arg:ident: $ty:ty)* $(,)?;)*) => {$(
        #[doc = concat!("No variable of this FMU is a ", $type_name, ": refuses every value reference.")]
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(
            instance: fmi3Instance,
            valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            $($arg: $ty,)*
        ) -> fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    stringify!($name),
                    $type_name,
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $pinned = Some($name);
    )*};
}
