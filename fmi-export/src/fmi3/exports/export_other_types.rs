//! The getters and setters of the FMI 3 types beyond the table's, under their C names, for
//! [`crate::export_fmi3!`]: UInt64, the structural parameters' type, forwards to the layer; those
//! of the types the FMU has no variable of (Float32, the small integers, Binary, Clock) refuse
//! every value reference, naming its variable.

/// Part of [`crate::export_fmi3!`], which invokes it.
#[doc(hidden)]
#[macro_export]
macro_rules! export_fmi3_other_types {
    ($model:ty) => {
        /// No variable of this FMU is a Float32: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetFloat32(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _values: *mut $crate::fmi3::exports::sys::fmi3Float32,
            _nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3GetFloat32",
                    "Float32",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetFloat32TYPE = Some(fmi3GetFloat32);
        /// No variable of this FMU is a Int8: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetInt8(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _values: *mut $crate::fmi3::exports::sys::fmi3Int8,
            _nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3GetInt8",
                    "Int8",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetInt8TYPE = Some(fmi3GetInt8);
        /// No variable of this FMU is a UInt8: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetUInt8(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _values: *mut $crate::fmi3::exports::sys::fmi3UInt8,
            _nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3GetUInt8",
                    "UInt8",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetUInt8TYPE = Some(fmi3GetUInt8);
        /// No variable of this FMU is a Int16: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetInt16(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _values: *mut $crate::fmi3::exports::sys::fmi3Int16,
            _nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3GetInt16",
                    "Int16",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetInt16TYPE = Some(fmi3GetInt16);
        /// No variable of this FMU is a UInt16: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetUInt16(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _values: *mut $crate::fmi3::exports::sys::fmi3UInt16,
            _nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3GetUInt16",
                    "UInt16",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetUInt16TYPE = Some(fmi3GetUInt16);
        /// No variable of this FMU is a UInt32: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetUInt32(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _values: *mut $crate::fmi3::exports::sys::fmi3UInt32,
            _nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3GetUInt32",
                    "UInt32",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetUInt32TYPE = Some(fmi3GetUInt32);
        /// Reads the structural parameters (FMI 3's only UInt64 variables).
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetUInt64(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *mut $crate::fmi3::exports::sys::fmi3UInt64,
            nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3GetUInt64::<$model>(
                    instance,
                    valueReferences,
                    nValueReferences,
                    values,
                    nValues,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetUInt64TYPE = Some(fmi3GetUInt64);
        /// No variable of this FMU is a Binary: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetBinary(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _valueSizes: *mut usize,
            _values: *mut $crate::fmi3::exports::sys::fmi3Binary,
            _nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3GetBinary",
                    "Binary",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetBinaryTYPE = Some(fmi3GetBinary);
        /// No variable of this FMU is a Clock: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetClock(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _values: *mut $crate::fmi3::exports::sys::fmi3Clock,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3GetClock",
                    "Clock",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetClockTYPE = Some(fmi3GetClock);
        /// No variable of this FMU is a Float32: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetFloat32(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _values: *const $crate::fmi3::exports::sys::fmi3Float32,
            _nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3SetFloat32",
                    "Float32",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetFloat32TYPE = Some(fmi3SetFloat32);
        /// No variable of this FMU is a Int8: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetInt8(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _values: *const $crate::fmi3::exports::sys::fmi3Int8,
            _nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3SetInt8",
                    "Int8",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetInt8TYPE = Some(fmi3SetInt8);
        /// No variable of this FMU is a UInt8: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetUInt8(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _values: *const $crate::fmi3::exports::sys::fmi3UInt8,
            _nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3SetUInt8",
                    "UInt8",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetUInt8TYPE = Some(fmi3SetUInt8);
        /// No variable of this FMU is a Int16: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetInt16(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _values: *const $crate::fmi3::exports::sys::fmi3Int16,
            _nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3SetInt16",
                    "Int16",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetInt16TYPE = Some(fmi3SetInt16);
        /// No variable of this FMU is a UInt16: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetUInt16(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _values: *const $crate::fmi3::exports::sys::fmi3UInt16,
            _nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3SetUInt16",
                    "UInt16",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetUInt16TYPE = Some(fmi3SetUInt16);
        /// No variable of this FMU is a UInt32: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetUInt32(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _values: *const $crate::fmi3::exports::sys::fmi3UInt32,
            _nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3SetUInt32",
                    "UInt32",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetUInt32TYPE = Some(fmi3SetUInt32);
        /// Sets the structural parameters (FMI 3's only UInt64 variables).
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetUInt64(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *const $crate::fmi3::exports::sys::fmi3UInt64,
            nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3SetUInt64::<$model>(
                    instance,
                    valueReferences,
                    nValueReferences,
                    values,
                    nValues,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetUInt64TYPE = Some(fmi3SetUInt64);
        /// No variable of this FMU is a Binary: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetBinary(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _valueSizes: *const usize,
            _values: *const $crate::fmi3::exports::sys::fmi3Binary,
            _nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3SetBinary",
                    "Binary",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetBinaryTYPE = Some(fmi3SetBinary);
        /// No variable of this FMU is a Clock: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetClock(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _values: *const $crate::fmi3::exports::sys::fmi3Clock,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3SetClock",
                    "Clock",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetClockTYPE = Some(fmi3SetClock);
    };
}
