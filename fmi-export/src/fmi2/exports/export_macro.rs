//! [`crate::export_fmi2!`]: the 34 functions under their C names, forwarding to the generic ones.

/// Exports the 34 `fmi2*` functions of a co-simulation FMU for the model type `$model`
/// (one invocation per shared library); `const _: fmi2XxxTYPE = Some(fmi2Xxx)` pins every
/// signature to the official header.
#[macro_export]
macro_rules! export_fmi2 {
    ($model:ty) => {
        /// See `fmi_export::fmi2::exports::fmi2GetTypesPlatform`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetTypesPlatform() -> *const ::std::ffi::c_char {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            $crate::fmi2::exports::fmi2GetTypesPlatform()
        }
        const _: $crate::fmi2::exports::sys::fmi2GetTypesPlatformTYPE = Some(fmi2GetTypesPlatform);
        /// See `fmi_export::fmi2::exports::fmi2GetVersion`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetVersion() -> *const ::std::ffi::c_char {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            $crate::fmi2::exports::fmi2GetVersion()
        }
        const _: $crate::fmi2::exports::sys::fmi2GetVersionTYPE = Some(fmi2GetVersion);
        $crate::forward_export!(
            fmi2, $model,
            fmi2Instantiate: fmi2InstantiateTYPE,
            (
            instanceName: $crate::fmi2::exports::sys::fmi2String,
            fmuType: $crate::fmi2::exports::sys::fmi2Type,
            fmuGUID: $crate::fmi2::exports::sys::fmi2String,
            _fmuResourceLocation: $crate::fmi2::exports::sys::fmi2String,
            functions: *const $crate::fmi2::exports::sys::fmi2CallbackFunctions,
            _visible: $crate::fmi2::exports::sys::fmi2Boolean,
            loggingOn: $crate::fmi2::exports::sys::fmi2Boolean,
            ) -> $crate::fmi2::exports::sys::fmi2Component
        );
        /// See `fmi_export::fmi2::exports::fmi2FreeInstance`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2FreeInstance(c: $crate::fmi2::exports::sys::fmi2Component) {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2FreeInstance::<$model>(c) }
        }
        const _: $crate::fmi2::exports::sys::fmi2FreeInstanceTYPE = Some(fmi2FreeInstance);
        $crate::forward_export!(
            fmi2, $model,
            fmi2SetDebugLogging: fmi2SetDebugLoggingTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            loggingOn: $crate::fmi2::exports::sys::fmi2Boolean,
            nCategories: usize,
            categories: *const $crate::fmi2::exports::sys::fmi2String,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2SetupExperiment: fmi2SetupExperimentTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            toleranceDefined: $crate::fmi2::exports::sys::fmi2Boolean,
            tolerance: $crate::fmi2::exports::sys::fmi2Real,
            startTime: $crate::fmi2::exports::sys::fmi2Real,
            stopTimeDefined: $crate::fmi2::exports::sys::fmi2Boolean,
            stopTime: $crate::fmi2::exports::sys::fmi2Real,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2EnterInitializationMode: fmi2EnterInitializationModeTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2ExitInitializationMode: fmi2ExitInitializationModeTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2Terminate: fmi2TerminateTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2Reset: fmi2ResetTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2GetReal: fmi2GetRealTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *mut $crate::fmi2::exports::sys::fmi2Real,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2GetInteger: fmi2GetIntegerTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *mut $crate::fmi2::exports::sys::fmi2Integer,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2GetBoolean: fmi2GetBooleanTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *mut $crate::fmi2::exports::sys::fmi2Boolean,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2GetString: fmi2GetStringTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *mut $crate::fmi2::exports::sys::fmi2String,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2SetReal: fmi2SetRealTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *const $crate::fmi2::exports::sys::fmi2Real,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2SetInteger: fmi2SetIntegerTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *const $crate::fmi2::exports::sys::fmi2Integer,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2SetBoolean: fmi2SetBooleanTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *const $crate::fmi2::exports::sys::fmi2Boolean,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2SetString: fmi2SetStringTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *const $crate::fmi2::exports::sys::fmi2String,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2GetFMUstate: fmi2GetFMUstateTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            FMUstate: *mut $crate::fmi2::exports::sys::fmi2FMUstate,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2SetFMUstate: fmi2SetFMUstateTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            FMUstate: $crate::fmi2::exports::sys::fmi2FMUstate,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2FreeFMUstate: fmi2FreeFMUstateTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            FMUstate: *mut $crate::fmi2::exports::sys::fmi2FMUstate,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2SerializedFMUstateSize: fmi2SerializedFMUstateSizeTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            FMUstate: $crate::fmi2::exports::sys::fmi2FMUstate,
            size: *mut usize,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2SerializeFMUstate: fmi2SerializeFMUstateTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            FMUstate: $crate::fmi2::exports::sys::fmi2FMUstate,
            serializedState: *mut $crate::fmi2::exports::sys::fmi2Byte,
            size: usize,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2DeSerializeFMUstate: fmi2DeSerializeFMUstateTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            serializedState: *const $crate::fmi2::exports::sys::fmi2Byte,
            size: usize,
            FMUstate: *mut $crate::fmi2::exports::sys::fmi2FMUstate,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2GetDirectionalDerivative: fmi2GetDirectionalDerivativeTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            _vUnknown_ref: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            _nUnknown: usize,
            _vKnown_ref: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            _nKnown: usize,
            _dvKnown: *const $crate::fmi2::exports::sys::fmi2Real,
            _dvUnknown: *mut $crate::fmi2::exports::sys::fmi2Real,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2SetRealInputDerivatives: fmi2SetRealInputDerivativesTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            order: *const $crate::fmi2::exports::sys::fmi2Integer,
            value: *const $crate::fmi2::exports::sys::fmi2Real,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2GetRealOutputDerivatives: fmi2GetRealOutputDerivativesTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            order: *const $crate::fmi2::exports::sys::fmi2Integer,
            value: *mut $crate::fmi2::exports::sys::fmi2Real,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2DoStep: fmi2DoStepTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            currentCommunicationPoint: $crate::fmi2::exports::sys::fmi2Real,
            communicationStepSize: $crate::fmi2::exports::sys::fmi2Real,
            _noSetFMUStatePriorToCurrentPoint: $crate::fmi2::exports::sys::fmi2Boolean,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2CancelStep: fmi2CancelStepTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2GetStatus: fmi2GetStatusTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            _s: $crate::fmi2::exports::sys::fmi2StatusKind,
            value: *mut $crate::fmi2::exports::sys::fmi2Status,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2GetRealStatus: fmi2GetRealStatusTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            s: $crate::fmi2::exports::sys::fmi2StatusKind,
            value: *mut $crate::fmi2::exports::sys::fmi2Real,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2GetIntegerStatus: fmi2GetIntegerStatusTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            _s: $crate::fmi2::exports::sys::fmi2StatusKind,
            value: *mut $crate::fmi2::exports::sys::fmi2Integer,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2GetBooleanStatus: fmi2GetBooleanStatusTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            s: $crate::fmi2::exports::sys::fmi2StatusKind,
            value: *mut $crate::fmi2::exports::sys::fmi2Boolean,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
        $crate::forward_export!(
            fmi2, $model,
            fmi2GetStringStatus: fmi2GetStringStatusTYPE,
            (
            c: $crate::fmi2::exports::sys::fmi2Component,
            _s: $crate::fmi2::exports::sys::fmi2StatusKind,
            value: *mut $crate::fmi2::exports::sys::fmi2String,
            ) -> $crate::fmi2::exports::sys::fmi2Status
        );
    };
}
