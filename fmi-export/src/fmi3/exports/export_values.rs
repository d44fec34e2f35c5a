//! The getters and setters of the FMI 3 types the FMU has variables of under their C names, for
//! [`crate::export_fmi3!`]: Float64, Int32, Int64, Boolean and String, forwarding to the generic
//! functions.

/// Part of [`crate::export_fmi3!`], which invokes it.
#[doc(hidden)]
#[macro_export]
macro_rules! export_fmi3_values {
    ($model:ty) => {
        /// See `fmi_export::fmi3::exports::fmi3GetFloat64`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetFloat64(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *mut $crate::fmi3::exports::sys::fmi3Float64,
            nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3GetFloat64::<$model>(
                    instance,
                    valueReferences,
                    nValueReferences,
                    values,
                    nValues,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetFloat64TYPE = Some(fmi3GetFloat64);
        /// See `fmi_export::fmi3::exports::fmi3GetInt32`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetInt32(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *mut $crate::fmi3::exports::sys::fmi3Int32,
            nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3GetInt32::<$model>(
                    instance,
                    valueReferences,
                    nValueReferences,
                    values,
                    nValues,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetInt32TYPE = Some(fmi3GetInt32);
        /// See `fmi_export::fmi3::exports::fmi3GetInt64`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetInt64(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *mut $crate::fmi3::exports::sys::fmi3Int64,
            nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3GetInt64::<$model>(
                    instance,
                    valueReferences,
                    nValueReferences,
                    values,
                    nValues,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetInt64TYPE = Some(fmi3GetInt64);
        /// See `fmi_export::fmi3::exports::fmi3GetBoolean`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetBoolean(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3GetBoolean::<$model>(
                    instance,
                    valueReferences,
                    nValueReferences,
                    values,
                    nValues,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetBooleanTYPE = Some(fmi3GetBoolean);
        /// See `fmi_export::fmi3::exports::fmi3GetString`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetString(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *mut $crate::fmi3::exports::sys::fmi3String,
            nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3GetString::<$model>(
                    instance,
                    valueReferences,
                    nValueReferences,
                    values,
                    nValues,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetStringTYPE = Some(fmi3GetString);
        /// See `fmi_export::fmi3::exports::fmi3SetFloat64`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetFloat64(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *const $crate::fmi3::exports::sys::fmi3Float64,
            nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3SetFloat64::<$model>(
                    instance,
                    valueReferences,
                    nValueReferences,
                    values,
                    nValues,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetFloat64TYPE = Some(fmi3SetFloat64);
        /// See `fmi_export::fmi3::exports::fmi3SetInt32`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetInt32(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *const $crate::fmi3::exports::sys::fmi3Int32,
            nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3SetInt32::<$model>(
                    instance,
                    valueReferences,
                    nValueReferences,
                    values,
                    nValues,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetInt32TYPE = Some(fmi3SetInt32);
        /// See `fmi_export::fmi3::exports::fmi3SetInt64`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetInt64(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *const $crate::fmi3::exports::sys::fmi3Int64,
            nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3SetInt64::<$model>(
                    instance,
                    valueReferences,
                    nValueReferences,
                    values,
                    nValues,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetInt64TYPE = Some(fmi3SetInt64);
        /// See `fmi_export::fmi3::exports::fmi3SetBoolean`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetBoolean(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *const $crate::fmi3::exports::sys::fmi3Boolean,
            nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3SetBoolean::<$model>(
                    instance,
                    valueReferences,
                    nValueReferences,
                    values,
                    nValues,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetBooleanTYPE = Some(fmi3SetBoolean);
        /// See `fmi_export::fmi3::exports::fmi3SetString`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetString(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            values: *const $crate::fmi3::exports::sys::fmi3String,
            nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3SetString::<$model>(
                    instance,
                    valueReferences,
                    nValueReferences,
                    values,
                    nValues,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetStringTYPE = Some(fmi3SetString);
    };
}
