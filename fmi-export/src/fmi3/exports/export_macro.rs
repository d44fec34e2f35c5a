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
        $crate::forward_export!(
            fmi3, $model,
            fmi3InstantiateCoSimulation: fmi3InstantiateCoSimulationTYPE,
            (
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
            ) -> $crate::fmi3::exports::sys::fmi3Instance
        );
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
        $crate::forward_export!(
            fmi3, $model,
            fmi3SetDebugLogging: fmi3SetDebugLoggingTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            loggingOn: $crate::fmi3::exports::sys::fmi3Boolean,
            nCategories: usize,
            categories: *const $crate::fmi3::exports::sys::fmi3String,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3EnterInitializationMode: fmi3EnterInitializationModeTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            toleranceDefined: $crate::fmi3::exports::sys::fmi3Boolean,
            tolerance: $crate::fmi3::exports::sys::fmi3Float64,
            startTime: $crate::fmi3::exports::sys::fmi3Float64,
            stopTimeDefined: $crate::fmi3::exports::sys::fmi3Boolean,
            stopTime: $crate::fmi3::exports::sys::fmi3Float64,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3ExitInitializationMode: fmi3ExitInitializationModeTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3Terminate: fmi3TerminateTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3Reset: fmi3ResetTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3GetFMUState: fmi3GetFMUStateTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            FMUState: *mut $crate::fmi3::exports::sys::fmi3FMUState,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3SetFMUState: fmi3SetFMUStateTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            FMUState: $crate::fmi3::exports::sys::fmi3FMUState,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3FreeFMUState: fmi3FreeFMUStateTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            FMUState: *mut $crate::fmi3::exports::sys::fmi3FMUState,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3SerializedFMUStateSize: fmi3SerializedFMUStateSizeTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            FMUState: $crate::fmi3::exports::sys::fmi3FMUState,
            size: *mut usize,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3SerializeFMUState: fmi3SerializeFMUStateTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            FMUState: $crate::fmi3::exports::sys::fmi3FMUState,
            serializedState: *mut $crate::fmi3::exports::sys::fmi3Byte,
            size: usize,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3DeserializeFMUState: fmi3DeserializeFMUStateTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            serializedState: *const $crate::fmi3::exports::sys::fmi3Byte,
            size: usize,
            FMUState: *mut $crate::fmi3::exports::sys::fmi3FMUState,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3GetDirectionalDerivative: fmi3GetDirectionalDerivativeTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            unknowns: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nUnknowns: usize,
            knowns: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nKnowns: usize,
            seed: *const $crate::fmi3::exports::sys::fmi3Float64,
            nSeed: usize,
            sensitivity: *mut $crate::fmi3::exports::sys::fmi3Float64,
            nSensitivity: usize,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3GetOutputDerivatives: fmi3GetOutputDerivativesTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            valueReferences: *const $crate::fmi3::exports::sys::fmi3ValueReference,
            nValueReferences: usize,
            orders: *const $crate::fmi3::exports::sys::fmi3Int32,
            values: *mut $crate::fmi3::exports::sys::fmi3Float64,
            nValues: usize,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
        $crate::forward_export!(
            fmi3, $model,
            fmi3DoStep: fmi3DoStepTYPE,
            (
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            currentCommunicationPoint: $crate::fmi3::exports::sys::fmi3Float64,
            communicationStepSize: $crate::fmi3::exports::sys::fmi3Float64,
            noSetFMUStatePriorToCurrentPoint: $crate::fmi3::exports::sys::fmi3Boolean,
            eventHandlingNeeded: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            terminateSimulation: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            earlyReturn: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            lastSuccessfulTime: *mut $crate::fmi3::exports::sys::fmi3Float64,
            ) -> $crate::fmi3::exports::sys::fmi3Status
        );
    };
}
