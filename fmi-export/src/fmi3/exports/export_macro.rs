//! [`crate::export_fmi3!`]: every function of the FMI 3.0 headers under its C name, forwarding to
//! the generic ones of [`super`]: here the lifecycle, FMU states, derivatives and the step; the
//! getters and setters in `export_values.rs` and `export_other_types.rs`; the functions of capabilities the FMU does not have
//! (which refuse every call with a logged reason) in `export_unsupported.rs`.

/// Exports every `fmi3*` function of the FMI 3.0 headers for the model type `$model` (one
/// invocation per shared library, beside [`crate::export_fmi2!`]); `const _: fmi3XxxTYPE =
/// Some(fmi3Xxx)` pins every signature to the official header.
#[macro_export]
macro_rules! export_fmi3 {
    ($model:ty) => {
        $crate::export_fmi3_values!($model);
        $crate::export_fmi3_other_types!($model);
        $crate::export_fmi3_unsupported!($model);
        /// See `fmi_export::fmi3::exports::fmi3GetVersion`.
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
        /// See `fmi_export::fmi3::exports::fmi3InstantiateCoSimulation`.
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
        /// See `fmi_export::fmi3::exports::fmi3FreeInstance`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3FreeInstance(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3FreeInstance::<$model>(instance) }
        }
        const _: $crate::fmi3::exports::sys::fmi3FreeInstanceTYPE = Some(fmi3FreeInstance);
        /// See `fmi_export::fmi3::exports::fmi3SetDebugLogging`.
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
        /// See `fmi_export::fmi3::exports::fmi3EnterInitializationMode`.
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
        /// See `fmi_export::fmi3::exports::fmi3ExitInitializationMode`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3ExitInitializationMode(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3ExitInitializationMode::<$model>(instance) }
        }
        const _: $crate::fmi3::exports::sys::fmi3ExitInitializationModeTYPE =
            Some(fmi3ExitInitializationMode);
        /// See `fmi_export::fmi3::exports::fmi3Terminate`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3Terminate(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3Terminate::<$model>(instance) }
        }
        const _: $crate::fmi3::exports::sys::fmi3TerminateTYPE = Some(fmi3Terminate);
        /// See `fmi_export::fmi3::exports::fmi3Reset`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3Reset(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3Reset::<$model>(instance) }
        }
        const _: $crate::fmi3::exports::sys::fmi3ResetTYPE = Some(fmi3Reset);
        /// See `fmi_export::fmi3::exports::fmi3GetFMUState`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3GetFMUState(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            FMUState: *mut $crate::fmi3::exports::sys::fmi3FMUState,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3GetFMUState::<$model>(instance, FMUState) }
        }
        const _: $crate::fmi3::exports::sys::fmi3GetFMUStateTYPE = Some(fmi3GetFMUState);
        /// See `fmi_export::fmi3::exports::fmi3SetFMUState`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3SetFMUState(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            FMUState: $crate::fmi3::exports::sys::fmi3FMUState,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3SetFMUState::<$model>(instance, FMUState) }
        }
        const _: $crate::fmi3::exports::sys::fmi3SetFMUStateTYPE = Some(fmi3SetFMUState);
        /// See `fmi_export::fmi3::exports::fmi3FreeFMUState`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3FreeFMUState(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            FMUState: *mut $crate::fmi3::exports::sys::fmi3FMUState,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3FreeFMUState::<$model>(instance, FMUState) }
        }
        const _: $crate::fmi3::exports::sys::fmi3FreeFMUStateTYPE = Some(fmi3FreeFMUState);
        /// See `fmi_export::fmi3::exports::fmi3SerializedFMUStateSize`.
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
        /// See `fmi_export::fmi3::exports::fmi3SerializeFMUState`.
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
        /// See `fmi_export::fmi3::exports::fmi3DeserializeFMUState`.
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
        /// See `fmi_export::fmi3::exports::fmi3GetDirectionalDerivative`.
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
        /// See `fmi_export::fmi3::exports::fmi3GetOutputDerivatives`.
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
        /// See `fmi_export::fmi3::exports::fmi3DoStep`.
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
    };
}
