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
        /// The `fmi3*` functions of this library, under their C names (`#[no_mangle]`, exported
        /// from the shared library wherever they are declared).
        #[doc(hidden)]
        #[allow(non_snake_case, unused_imports)]
        pub mod fmi3_exports {
            use super::*;
            use $crate::fmi3::exports::sys::*;
            $crate::export_fmi3_values!($model);
            $crate::export_fmi3_other_types!($model);
            $crate::export_fmi3_unsupported!($model);
            /// See `fmi_export::fmi3::exports::fmi3GetVersion`.
            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3GetVersion() -> *const ::std::ffi::c_char {
                $crate::fmi3::exports::fmi3GetVersion()
            }
            const _: fmi3GetVersionTYPE = Some(fmi3GetVersion);
            /// Not provided: logs why and returns NULL.
            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3InstantiateModelExchange(
                _instanceName: fmi3String,
                _instantiationToken: fmi3String,
                _resourcePath: fmi3String,
                _visible: fmi3Boolean,
                _loggingOn: fmi3Boolean,
                instanceEnvironment: fmi3InstanceEnvironment,
                logMessage: fmi3LogMessageCallback,
            ) -> fmi3Instance {
                $crate::fmi3::exports::instantiate_other(
                    "fmi3InstantiateModelExchange",
                    instanceEnvironment,
                    logMessage,
                )
            }
            const _: fmi3InstantiateModelExchangeTYPE =
                Some(fmi3InstantiateModelExchange);
            $crate::forward_export!(fmi3, $model;
                fmi3InstantiateCoSimulation: fmi3InstantiateCoSimulationTYPE,
                    (instanceName: fmi3String, instantiationToken: fmi3String,
                    resourcePath: fmi3String, visible: fmi3Boolean, loggingOn: fmi3Boolean,
                    eventModeUsed: fmi3Boolean, earlyReturnAllowed: fmi3Boolean,
                    requiredIntermediateVariables: *const fmi3ValueReference,
                    nRequiredIntermediateVariables: usize,
                    instanceEnvironment: fmi3InstanceEnvironment,
                    logMessage: fmi3LogMessageCallback,
                    intermediateUpdate: fmi3IntermediateUpdateCallback) -> fmi3Instance;
            );
            /// Not provided: logs why and returns NULL.
            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3InstantiateScheduledExecution(
                _instanceName: fmi3String,
                _instantiationToken: fmi3String,
                _resourcePath: fmi3String,
                _visible: fmi3Boolean,
                _loggingOn: fmi3Boolean,
                instanceEnvironment: fmi3InstanceEnvironment,
                logMessage: fmi3LogMessageCallback,
                _clockUpdate: fmi3ClockUpdateCallback,
                _lockPreemption: fmi3LockPreemptionCallback,
                _unlockPreemption: fmi3UnlockPreemptionCallback,
            ) -> fmi3Instance {
                $crate::fmi3::exports::instantiate_other(
                    "fmi3InstantiateScheduledExecution",
                    instanceEnvironment,
                    logMessage,
                )
            }
            const _: fmi3InstantiateScheduledExecutionTYPE =
                Some(fmi3InstantiateScheduledExecution);
            /// See `fmi_export::fmi3::exports::fmi3FreeInstance`.
            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi3FreeInstance(
                instance: fmi3Instance,
            ) {
                // SAFETY: the master's arguments, passed on unchanged under the same contract.
                unsafe { $crate::fmi3::exports::fmi3FreeInstance::<$model>(instance) }
            }
            const _: fmi3FreeInstanceTYPE = Some(fmi3FreeInstance);
            $crate::forward_export!(fmi3, $model;
                fmi3SetDebugLogging: fmi3SetDebugLoggingTYPE, (instance: fmi3Instance,
                    loggingOn: fmi3Boolean, nCategories: usize,
                    categories: *const fmi3String) -> fmi3Status;
                fmi3EnterInitializationMode: fmi3EnterInitializationModeTYPE,
                    (instance: fmi3Instance, toleranceDefined: fmi3Boolean, tolerance: fmi3Float64,
                    startTime: fmi3Float64, stopTimeDefined: fmi3Boolean,
                    stopTime: fmi3Float64) -> fmi3Status;
                fmi3ExitInitializationMode: fmi3ExitInitializationModeTYPE,
                    (instance: fmi3Instance) -> fmi3Status;
                fmi3Terminate: fmi3TerminateTYPE, (instance: fmi3Instance) -> fmi3Status;
                fmi3Reset: fmi3ResetTYPE, (instance: fmi3Instance) -> fmi3Status;
                fmi3GetFMUState: fmi3GetFMUStateTYPE, (instance: fmi3Instance,
                    FMUState: *mut fmi3FMUState) -> fmi3Status;
                fmi3SetFMUState: fmi3SetFMUStateTYPE, (instance: fmi3Instance,
                    FMUState: fmi3FMUState) -> fmi3Status;
                fmi3FreeFMUState: fmi3FreeFMUStateTYPE, (instance: fmi3Instance,
                    FMUState: *mut fmi3FMUState) -> fmi3Status;
                fmi3SerializedFMUStateSize: fmi3SerializedFMUStateSizeTYPE,
                    (instance: fmi3Instance, FMUState: fmi3FMUState,
                    size: *mut usize) -> fmi3Status;
                fmi3SerializeFMUState: fmi3SerializeFMUStateTYPE, (instance: fmi3Instance,
                    FMUState: fmi3FMUState, serializedState: *mut fmi3Byte,
                    size: usize) -> fmi3Status;
                fmi3DeserializeFMUState: fmi3DeserializeFMUStateTYPE, (instance: fmi3Instance,
                    serializedState: *const fmi3Byte, size: usize,
                    FMUState: *mut fmi3FMUState) -> fmi3Status;
                fmi3GetDirectionalDerivative: fmi3GetDirectionalDerivativeTYPE,
                    (instance: fmi3Instance, unknowns: *const fmi3ValueReference, nUnknowns: usize,
                    knowns: *const fmi3ValueReference, nKnowns: usize, seed: *const fmi3Float64,
                    nSeed: usize, sensitivity: *mut fmi3Float64,
                    nSensitivity: usize) -> fmi3Status;
                fmi3GetOutputDerivatives: fmi3GetOutputDerivativesTYPE, (instance: fmi3Instance,
                    valueReferences: *const fmi3ValueReference, nValueReferences: usize,
                    orders: *const fmi3Int32, values: *mut fmi3Float64,
                    nValues: usize) -> fmi3Status;
                fmi3DoStep: fmi3DoStepTYPE, (instance: fmi3Instance,
                    currentCommunicationPoint: fmi3Float64, communicationStepSize: fmi3Float64,
                    noSetFMUStatePriorToCurrentPoint: fmi3Boolean,
                    eventHandlingNeeded: *mut fmi3Boolean, terminateSimulation: *mut fmi3Boolean,
                    earlyReturn: *mut fmi3Boolean,
                    lastSuccessfulTime: *mut fmi3Float64) -> fmi3Status;
            );
        }
    };
}
