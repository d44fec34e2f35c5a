//! [`crate::export_fmi3!`]: every function of the FMI 3.0 headers under its C name, forwarding to
//! the generic ones of [`super`]. Those of the types and capabilities the FMU does not have
//! refuse every non-empty request with a logged reason.

/// Exports every `fmi3*` function of the FMI 3.0 headers for the model type `$model` (one
/// invocation per shared library, beside [`crate::export_fmi2!`]); `const _: fmi3XxxTYPE =
/// Some(fmi3Xxx)` pins every signature to the official header.
#[macro_export]
macro_rules! export_fmi3 {
    ($model:ty) => {
        /// See `fmi2_slave::fmi3::exports::fmi3GetVersion`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetVersion() -> *const ::std::ffi::c_char {
            $crate::fmi3::exports::fmi3GetVersion()
        }
        const _: $crate::fmi3::exports::sys::fmi3GetVersionTYPE = Some(fmi3GetVersion);
        /// Not provided: logs why and returns NULL.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3InstantiateModelExchange(
            _instanceName: $crate::fmi3::exports::sys::fmi3String,
            _instantiationToken: $crate::fmi3::exports::sys::fmi3String,
            _resourcePath: $crate::fmi3::exports::sys::fmi3String,
            _visible: $crate::fmi3::exports::sys::fmi3Boolean,
            _loggingOn: $crate::fmi3::exports::sys::fmi3Boolean,
            instanceEnvironment: $crate::fmi3::exports::sys::fmi3InstanceEnvironment,
            logMessage: $crate::fmi3::exports::sys::fmi3LogMessageCallback,
        ) -> $crate::fmi3::exports::sys::fmi3Instance {
            $crate::fmi3::exports::instantiate_other(
                "fmi3InstantiateModelExchange",
                instanceEnvironment,
                logMessage,
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3InstantiateModelExchangeTYPE =
            Some(fmi3InstantiateModelExchange);
        /// See `fmi2_slave::fmi3::exports::fmi3InstantiateCoSimulation`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3InstantiateCoSimulation(
            instanceName: $crate::fmi3::exports::sys::fmi3String,
            instantiationToken: $crate::fmi3::exports::sys::fmi3String,
            resourcePath: $crate::fmi3::exports::sys::fmi3String,
            visible: $crate::fmi3::exports::sys::fmi3Boolean,
            loggingOn: $crate::fmi3::exports::sys::fmi3Boolean,
            eventModeUsed: $crate::fmi3::exports::sys::fmi3Boolean,
            earlyReturnAllowed: $crate::fmi3::exports::sys::fmi3Boolean,
            requiredIntermediateVariables: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nRequiredIntermediateVariables: usize,
            instanceEnvironment: $crate::fmi3::exports::sys::fmi3InstanceEnvironment,
            logMessage: $crate::fmi3::exports::sys::fmi3LogMessageCallback,
            intermediateUpdate: $crate::fmi3::exports::sys::fmi3IntermediateUpdateCallback,
        ) -> $crate::fmi3::exports::sys::fmi3Instance {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3InstantiateCoSimulation::<$model>(
                    instanceName,
                    instantiationToken,
                    resourcePath,
                    visible,
                    loggingOn,
                    eventModeUsed,
                    earlyReturnAllowed,
                    requiredIntermediateVariables,
                    nRequiredIntermediateVariables,
                    instanceEnvironment,
                    logMessage,
                    intermediateUpdate,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3InstantiateCoSimulationTYPE =
            Some(fmi3InstantiateCoSimulation);
        /// Not provided: logs why and returns NULL.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3InstantiateScheduledExecution(
            _instanceName: $crate::fmi3::exports::sys::fmi3String,
            _instantiationToken: $crate::fmi3::exports::sys::fmi3String,
            _resourcePath: $crate::fmi3::exports::sys::fmi3String,
            _visible: $crate::fmi3::exports::sys::fmi3Boolean,
            _loggingOn: $crate::fmi3::exports::sys::fmi3Boolean,
            instanceEnvironment: $crate::fmi3::exports::sys::fmi3InstanceEnvironment,
            logMessage: $crate::fmi3::exports::sys::fmi3LogMessageCallback,
            _clockUpdate: $crate::fmi3::exports::sys::fmi3ClockUpdateCallback,
            _lockPreemption: $crate::fmi3::exports::sys::fmi3LockPreemptionCallback,
            _unlockPreemption: $crate::fmi3::exports::sys::fmi3UnlockPreemptionCallback,
        ) -> $crate::fmi3::exports::sys::fmi3Instance {
            $crate::fmi3::exports::instantiate_other(
                "fmi3InstantiateScheduledExecution",
                instanceEnvironment,
                logMessage,
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3InstantiateScheduledExecutionTYPE =
            Some(fmi3InstantiateScheduledExecution);
        /// See `fmi2_slave::fmi3::exports::fmi3FreeInstance`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3FreeInstance(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3FreeInstance::<$model>(instance) }
        }
        const _: $crate::fmi3::exports::sys::fmi3FreeInstanceTYPE = Some(fmi3FreeInstance);
        /// See `fmi2_slave::fmi3::exports::fmi3SetDebugLogging`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetDebugLogging(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            loggingOn: $crate::fmi3::exports::sys::fmi3Boolean,
            nCategories: usize,
            categories: *const $crate::fmi3::exports::sys::fmi3String,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3SetDebugLogging::<$model>(
                    instance,
                    loggingOn,
                    nCategories,
                    categories,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetDebugLoggingTYPE = Some(fmi3SetDebugLogging);
        /// See `fmi2_slave::fmi3::exports::fmi3EnterInitializationMode`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3EnterInitializationMode(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            toleranceDefined: $crate::fmi3::exports::sys::fmi3Boolean,
            tolerance: $crate::fmi3::exports::sys::fmi3Float64,
            startTime: $crate::fmi3::exports::sys::fmi3Float64,
            stopTimeDefined: $crate::fmi3::exports::sys::fmi3Boolean,
            stopTime: $crate::fmi3::exports::sys::fmi3Float64,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3EnterInitializationMode::<$model>(
                    instance,
                    toleranceDefined,
                    tolerance,
                    startTime,
                    stopTimeDefined,
                    stopTime,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3EnterInitializationModeTYPE =
            Some(fmi3EnterInitializationMode);
        /// See `fmi2_slave::fmi3::exports::fmi3ExitInitializationMode`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3ExitInitializationMode(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3ExitInitializationMode::<$model>(instance) }
        }
        const _: $crate::fmi3::exports::sys::fmi3ExitInitializationModeTYPE =
            Some(fmi3ExitInitializationMode);
        /// Not supported: the FMU has no event mode (hasEventMode = false).
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3EnterEventMode(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3EnterEventMode",
                "the FMU has no event mode (hasEventMode = false)",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3EnterEventModeTYPE = Some(fmi3EnterEventMode);
        /// See `fmi2_slave::fmi3::exports::fmi3Terminate`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3Terminate(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3Terminate::<$model>(instance) }
        }
        const _: $crate::fmi3::exports::sys::fmi3TerminateTYPE = Some(fmi3Terminate);
        /// See `fmi2_slave::fmi3::exports::fmi3Reset`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3Reset(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3Reset::<$model>(instance) }
        }
        const _: $crate::fmi3::exports::sys::fmi3ResetTYPE = Some(fmi3Reset);
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
        /// See `fmi2_slave::fmi3::exports::fmi3GetFloat64`.
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
        /// See `fmi2_slave::fmi3::exports::fmi3GetInt32`.
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
        /// See `fmi2_slave::fmi3::exports::fmi3GetInt64`.
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
        /// No variable of this FMU is a UInt64: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetUInt64(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _values: *mut $crate::fmi3::exports::sys::fmi3UInt64,
            _nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3GetUInt64",
                    "UInt64",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetUInt64TYPE = Some(fmi3GetUInt64);
        /// See `fmi2_slave::fmi3::exports::fmi3GetBoolean`.
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
        /// See `fmi2_slave::fmi3::exports::fmi3GetString`.
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
        /// See `fmi2_slave::fmi3::exports::fmi3SetFloat64`.
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
        /// See `fmi2_slave::fmi3::exports::fmi3SetInt32`.
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
        /// See `fmi2_slave::fmi3::exports::fmi3SetInt64`.
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
        /// No variable of this FMU is a UInt64: refuses every value reference.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetUInt64(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            _values: *const $crate::fmi3::exports::sys::fmi3UInt64,
            _nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::no_variable_of_type::<$model>(
                    instance,
                    "fmi3SetUInt64",
                    "UInt64",
                    valueReferences,
                    nValueReferences,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetUInt64TYPE = Some(fmi3SetUInt64);
        /// See `fmi2_slave::fmi3::exports::fmi3SetBoolean`.
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
        /// See `fmi2_slave::fmi3::exports::fmi3SetString`.
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
        /// Not supported: the dependencies are those of modelDescription.xml's ModelStructure.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetNumberOfVariableDependencies(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _valueReference: $crate::fmi3::exports::sys::fmi3ValueReference,
            _nDependencies: *mut usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3GetNumberOfVariableDependencies",
                "the dependencies are those of modelDescription.xml's ModelStructure",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3GetNumberOfVariableDependenciesTYPE =
            Some(fmi3GetNumberOfVariableDependencies);
        /// Not supported: the dependencies are those of modelDescription.xml's ModelStructure.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetVariableDependencies(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _dependent: $crate::fmi3::exports::sys::fmi3ValueReference,
            _elementIndicesOfDependent: *mut usize,
            _independents: *mut $crate::fmi3::exports::sys::fmi3ValueReference,
            _elementIndicesOfIndependents: *mut usize,
            _dependencyKinds: *mut $crate::fmi3::exports::sys::fmi3DependencyKind,
            _nDependencies: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3GetVariableDependencies",
                "the dependencies are those of modelDescription.xml's ModelStructure",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3GetVariableDependenciesTYPE =
            Some(fmi3GetVariableDependencies);
        /// See `fmi2_slave::fmi3::exports::fmi3GetFMUState`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetFMUState(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            FMUState: *mut $crate::fmi3::exports::sys::fmi3FMUState,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3GetFMUState::<$model>(instance, FMUState) }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetFMUStateTYPE = Some(fmi3GetFMUState);
        /// See `fmi2_slave::fmi3::exports::fmi3SetFMUState`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetFMUState(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            FMUState: $crate::fmi3::exports::sys::fmi3FMUState,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3SetFMUState::<$model>(instance, FMUState) }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetFMUStateTYPE = Some(fmi3SetFMUState);
        /// See `fmi2_slave::fmi3::exports::fmi3FreeFMUState`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3FreeFMUState(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            FMUState: *mut $crate::fmi3::exports::sys::fmi3FMUState,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3FreeFMUState::<$model>(instance, FMUState) }
        }
        const _: $crate::fmi3::exports::sys::fmi3FreeFMUStateTYPE = Some(fmi3FreeFMUState);
        /// See `fmi2_slave::fmi3::exports::fmi3SerializedFMUStateSize`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SerializedFMUStateSize(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            FMUState: $crate::fmi3::exports::sys::fmi3FMUState,
            size: *mut usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3SerializedFMUStateSize::<$model>(
                    instance, FMUState, size,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SerializedFMUStateSizeTYPE =
            Some(fmi3SerializedFMUStateSize);
        /// See `fmi2_slave::fmi3::exports::fmi3SerializeFMUState`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SerializeFMUState(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            FMUState: $crate::fmi3::exports::sys::fmi3FMUState,
            serializedState: *mut $crate::fmi3::exports::sys::fmi3Byte,
            size: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3SerializeFMUState::<$model>(
                    instance,
                    FMUState,
                    serializedState,
                    size,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3SerializeFMUStateTYPE =
            Some(fmi3SerializeFMUState);
        /// See `fmi2_slave::fmi3::exports::fmi3DeserializeFMUState`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3DeserializeFMUState(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            serializedState: *const $crate::fmi3::exports::sys::fmi3Byte,
            size: usize,
            FMUState: *mut $crate::fmi3::exports::sys::fmi3FMUState,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3DeserializeFMUState::<$model>(
                    instance,
                    serializedState,
                    size,
                    FMUState,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3DeserializeFMUStateTYPE =
            Some(fmi3DeserializeFMUState);
        /// See `fmi2_slave::fmi3::exports::fmi3GetDirectionalDerivative`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetDirectionalDerivative(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            unknowns: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nUnknowns: usize,
            knowns: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nKnowns: usize,
            seed: *const $crate::fmi3::exports::sys::fmi3Float64,
            nSeed: usize,
            sensitivity: *mut $crate::fmi3::exports::sys::fmi3Float64,
            nSensitivity: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3GetDirectionalDerivative::<$model>(
                    instance,
                    unknowns,
                    nUnknowns,
                    knowns,
                    nKnowns,
                    seed,
                    nSeed,
                    sensitivity,
                    nSensitivity,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetDirectionalDerivativeTYPE =
            Some(fmi3GetDirectionalDerivative);
        /// Not supported: adjoint derivatives are not provided (providesAdjointDerivatives = false).
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetAdjointDerivative(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _unknowns: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            _nUnknowns: usize,
            _knowns: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            _nKnowns: usize,
            _seed: *const $crate::fmi3::exports::sys::fmi3Float64,
            _nSeed: usize,
            _sensitivity: *mut $crate::fmi3::exports::sys::fmi3Float64,
            _nSensitivity: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3GetAdjointDerivative",
                "adjoint derivatives are not provided (providesAdjointDerivatives = false)",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3GetAdjointDerivativeTYPE =
            Some(fmi3GetAdjointDerivative);
        /// Not supported: the FMU has no structural parameters.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3EnterConfigurationMode(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3EnterConfigurationMode",
                "the FMU has no structural parameters",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3EnterConfigurationModeTYPE =
            Some(fmi3EnterConfigurationMode);
        /// Not supported: the FMU has no structural parameters.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3ExitConfigurationMode(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3ExitConfigurationMode",
                "the FMU has no structural parameters",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3ExitConfigurationModeTYPE =
            Some(fmi3ExitConfigurationMode);
        /// Not supported: the FMU has no clocks.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetIntervalDecimal(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            _nValueReferences: usize,
            _intervals: *mut $crate::fmi3::exports::sys::fmi3Float64,
            _qualifiers: *mut $crate::fmi3::exports::sys::fmi3IntervalQualifier,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3GetIntervalDecimal",
                "the FMU has no clocks",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3GetIntervalDecimalTYPE =
            Some(fmi3GetIntervalDecimal);
        /// Not supported: the FMU has no clocks.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetIntervalFraction(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            _nValueReferences: usize,
            _counters: *mut $crate::fmi3::exports::sys::fmi3UInt64,
            _resolutions: *mut $crate::fmi3::exports::sys::fmi3UInt64,
            _qualifiers: *mut $crate::fmi3::exports::sys::fmi3IntervalQualifier,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3GetIntervalFraction",
                "the FMU has no clocks",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3GetIntervalFractionTYPE =
            Some(fmi3GetIntervalFraction);
        /// Not supported: the FMU has no clocks.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetShiftDecimal(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            _nValueReferences: usize,
            _shifts: *mut $crate::fmi3::exports::sys::fmi3Float64,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3GetShiftDecimal",
                "the FMU has no clocks",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3GetShiftDecimalTYPE = Some(fmi3GetShiftDecimal);
        /// Not supported: the FMU has no clocks.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetShiftFraction(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            _nValueReferences: usize,
            _counters: *mut $crate::fmi3::exports::sys::fmi3UInt64,
            _resolutions: *mut $crate::fmi3::exports::sys::fmi3UInt64,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3GetShiftFraction",
                "the FMU has no clocks",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3GetShiftFractionTYPE = Some(fmi3GetShiftFraction);
        /// Not supported: the FMU has no clocks.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetIntervalDecimal(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            _nValueReferences: usize,
            _intervals: *const $crate::fmi3::exports::sys::fmi3Float64,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3SetIntervalDecimal",
                "the FMU has no clocks",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3SetIntervalDecimalTYPE =
            Some(fmi3SetIntervalDecimal);
        /// Not supported: the FMU has no clocks.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetIntervalFraction(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            _nValueReferences: usize,
            _counters: *const $crate::fmi3::exports::sys::fmi3UInt64,
            _resolutions: *const $crate::fmi3::exports::sys::fmi3UInt64,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3SetIntervalFraction",
                "the FMU has no clocks",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3SetIntervalFractionTYPE =
            Some(fmi3SetIntervalFraction);
        /// Not supported: the FMU has no clocks.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetShiftDecimal(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            _nValueReferences: usize,
            _shifts: *const $crate::fmi3::exports::sys::fmi3Float64,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3SetShiftDecimal",
                "the FMU has no clocks",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3SetShiftDecimalTYPE = Some(fmi3SetShiftDecimal);
        /// Not supported: the FMU has no clocks.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetShiftFraction(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            _nValueReferences: usize,
            _counters: *const $crate::fmi3::exports::sys::fmi3UInt64,
            _resolutions: *const $crate::fmi3::exports::sys::fmi3UInt64,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3SetShiftFraction",
                "the FMU has no clocks",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3SetShiftFractionTYPE = Some(fmi3SetShiftFraction);
        /// Not supported: the FMU has no event mode (hasEventMode = false).
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3EvaluateDiscreteStates(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3EvaluateDiscreteStates",
                "the FMU has no event mode (hasEventMode = false)",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3EvaluateDiscreteStatesTYPE =
            Some(fmi3EvaluateDiscreteStates);
        /// Not supported: the FMU has no event mode (hasEventMode = false).
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3UpdateDiscreteStates(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _discreteStatesNeedUpdate: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            _terminateSimulation: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            _nominalsOfContinuousStatesChanged: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            _valuesOfContinuousStatesChanged: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            _nextEventTimeDefined: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            _nextEventTime: *mut $crate::fmi3::exports::sys::fmi3Float64,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3UpdateDiscreteStates",
                "the FMU has no event mode (hasEventMode = false)",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3UpdateDiscreteStatesTYPE =
            Some(fmi3UpdateDiscreteStates);
        /// Not supported: model exchange is not provided.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3EnterContinuousTimeMode(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3EnterContinuousTimeMode",
                "model exchange is not provided",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3EnterContinuousTimeModeTYPE =
            Some(fmi3EnterContinuousTimeMode);
        /// Not supported: model exchange is not provided.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3CompletedIntegratorStep(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _noSetFMUStatePriorToCurrentPoint: $crate::fmi3::exports::sys::fmi3Boolean,
            _enterEventMode: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            _terminateSimulation: *mut $crate::fmi3::exports::sys::fmi3Boolean,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3CompletedIntegratorStep",
                "model exchange is not provided",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3CompletedIntegratorStepTYPE =
            Some(fmi3CompletedIntegratorStep);
        /// Not supported: model exchange is not provided.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetTime(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _time: $crate::fmi3::exports::sys::fmi3Float64,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3SetTime",
                "model exchange is not provided",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3SetTimeTYPE = Some(fmi3SetTime);
        /// Not supported: model exchange is not provided.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetContinuousStates(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _continuousStates: *const $crate::fmi3::exports::sys::fmi3Float64,
            _nContinuousStates: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3SetContinuousStates",
                "model exchange is not provided",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3SetContinuousStatesTYPE =
            Some(fmi3SetContinuousStates);
        /// Not supported: model exchange is not provided.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetContinuousStateDerivatives(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _derivatives: *mut $crate::fmi3::exports::sys::fmi3Float64,
            _nContinuousStates: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3GetContinuousStateDerivatives",
                "model exchange is not provided",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3GetContinuousStateDerivativesTYPE =
            Some(fmi3GetContinuousStateDerivatives);
        /// Not supported: model exchange is not provided.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetEventIndicators(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _eventIndicators: *mut $crate::fmi3::exports::sys::fmi3Float64,
            _nEventIndicators: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3GetEventIndicators",
                "model exchange is not provided",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3GetEventIndicatorsTYPE =
            Some(fmi3GetEventIndicators);
        /// Not supported: model exchange is not provided.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetContinuousStates(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _continuousStates: *mut $crate::fmi3::exports::sys::fmi3Float64,
            _nContinuousStates: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3GetContinuousStates",
                "model exchange is not provided",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3GetContinuousStatesTYPE =
            Some(fmi3GetContinuousStates);
        /// Not supported: model exchange is not provided.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetNominalsOfContinuousStates(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _nominals: *mut $crate::fmi3::exports::sys::fmi3Float64,
            _nContinuousStates: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3GetNominalsOfContinuousStates",
                "model exchange is not provided",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3GetNominalsOfContinuousStatesTYPE =
            Some(fmi3GetNominalsOfContinuousStates);
        /// Not supported: model exchange is not provided.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetNumberOfEventIndicators(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _nEventIndicators: *mut usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3GetNumberOfEventIndicators",
                "model exchange is not provided",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3GetNumberOfEventIndicatorsTYPE =
            Some(fmi3GetNumberOfEventIndicators);
        /// Not supported: model exchange is not provided.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetNumberOfContinuousStates(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _nContinuousStates: *mut usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3GetNumberOfContinuousStates",
                "model exchange is not provided",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3GetNumberOfContinuousStatesTYPE =
            Some(fmi3GetNumberOfContinuousStates);
        /// Not supported: the FMU has no event mode (hasEventMode = false).
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3EnterStepMode(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3EnterStepMode",
                "the FMU has no event mode (hasEventMode = false)",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3EnterStepModeTYPE = Some(fmi3EnterStepMode);
        /// See `fmi2_slave::fmi3::exports::fmi3GetOutputDerivatives`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetOutputDerivatives(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            orders: *const $crate::fmi3::exports::sys::fmi3Int32,
            values: *mut $crate::fmi3::exports::sys::fmi3Float64,
            nValues: usize,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3GetOutputDerivatives::<$model>(
                    instance,
                    valueReferences,
                    nValueReferences,
                    orders,
                    values,
                    nValues,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetOutputDerivativesTYPE =
            Some(fmi3GetOutputDerivatives);
        /// See `fmi2_slave::fmi3::exports::fmi3DoStep`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3DoStep(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            currentCommunicationPoint: $crate::fmi3::exports::sys::fmi3Float64,
            communicationStepSize: $crate::fmi3::exports::sys::fmi3Float64,
            noSetFMUStatePriorToCurrentPoint: $crate::fmi3::exports::sys::fmi3Boolean,
            eventHandlingNeeded: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            terminateSimulation: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            earlyReturn: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            lastSuccessfulTime: *mut $crate::fmi3::exports::sys::fmi3Float64,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3DoStep::<$model>(
                    instance,
                    currentCommunicationPoint,
                    communicationStepSize,
                    noSetFMUStatePriorToCurrentPoint,
                    eventHandlingNeeded,
                    terminateSimulation,
                    earlyReturn,
                    lastSuccessfulTime,
                )
            }
        }
        const _: $crate::fmi3::exports::sys::fmi3DoStepTYPE = Some(fmi3DoStep);
        /// Not supported: scheduled execution is not provided.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3ActivateModelPartition(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            _clockReference: $crate::fmi3::exports::sys::fmi3ValueReference,
            _activationTime: $crate::fmi3::exports::sys::fmi3Float64,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3ActivateModelPartition",
                "scheduled execution is not provided",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3ActivateModelPartitionTYPE =
            Some(fmi3ActivateModelPartition);
    };
}
