//! [`crate::export_fmi2!`]: the 34 functions under their C names, forwarding to the generic ones.

/// Exports the 34 `fmi2*` functions of a co-simulation FMU for the model type `$model`
/// (one invocation per shared library); `const _: fmi2XxxTYPE = Some(fmi2Xxx)` pins every
/// signature to the official header.
#[macro_export]
macro_rules! export_fmi2 {
    ($model:ty) => {
        /// The `fmi2*` functions of this library, under their C names (`#[no_mangle]`, exported
        /// from the shared library wherever they are declared).
        #[doc(hidden)]
        #[allow(non_snake_case, unused_imports)]
        pub mod fmi2_exports {
            use super::*;
            use $crate::fmi2::exports::sys::*;
            /// See `fmi_export::fmi2::exports::fmi2GetTypesPlatform`.
            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2GetTypesPlatform() -> *const ::std::ffi::c_char {
                // SAFETY: the master's arguments, passed on unchanged under the same contract.
                $crate::fmi2::exports::fmi2GetTypesPlatform()
            }
            const _: fmi2GetTypesPlatformTYPE = Some(fmi2GetTypesPlatform);
            /// See `fmi_export::fmi2::exports::fmi2GetVersion`.
            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2GetVersion() -> *const ::std::ffi::c_char {
                // SAFETY: the master's arguments, passed on unchanged under the same contract.
                $crate::fmi2::exports::fmi2GetVersion()
            }
            const _: fmi2GetVersionTYPE = Some(fmi2GetVersion);
            $crate::forward_export!(fmi2, $model;
                fmi2Instantiate: fmi2InstantiateTYPE, (instanceName: fmi2String, fmuType: fmi2Type,
                    fmuGUID: fmi2String, _fmuResourceLocation: fmi2String,
                    functions: *const fmi2CallbackFunctions, _visible: fmi2Boolean,
                    loggingOn: fmi2Boolean) -> fmi2Component;
            );
            /// See `fmi_export::fmi2::exports::fmi2FreeInstance`.
            #[unsafe(no_mangle)]
            pub unsafe extern "C" fn fmi2FreeInstance(c: fmi2Component) {
                // SAFETY: the master's arguments, passed on unchanged under the same contract.
                unsafe { $crate::fmi2::exports::fmi2FreeInstance::<$model>(c) }
            }
            const _: fmi2FreeInstanceTYPE = Some(fmi2FreeInstance);
            $crate::forward_export!(fmi2, $model;
                fmi2SetDebugLogging: fmi2SetDebugLoggingTYPE, (c: fmi2Component,
                    loggingOn: fmi2Boolean, nCategories: usize,
                    categories: *const fmi2String) -> fmi2Status;
                fmi2SetupExperiment: fmi2SetupExperimentTYPE, (c: fmi2Component,
                    toleranceDefined: fmi2Boolean, tolerance: fmi2Real, startTime: fmi2Real,
                    stopTimeDefined: fmi2Boolean, stopTime: fmi2Real) -> fmi2Status;
                fmi2EnterInitializationMode: fmi2EnterInitializationModeTYPE,
                    (c: fmi2Component) -> fmi2Status;
                fmi2ExitInitializationMode: fmi2ExitInitializationModeTYPE,
                    (c: fmi2Component) -> fmi2Status;
                fmi2Terminate: fmi2TerminateTYPE, (c: fmi2Component) -> fmi2Status;
                fmi2Reset: fmi2ResetTYPE, (c: fmi2Component) -> fmi2Status;
                fmi2GetReal: fmi2GetRealTYPE, (c: fmi2Component, vr: *const fmi2ValueReference,
                    nvr: usize, value: *mut fmi2Real) -> fmi2Status;
                fmi2GetInteger: fmi2GetIntegerTYPE, (c: fmi2Component,
                    vr: *const fmi2ValueReference, nvr: usize,
                    value: *mut fmi2Integer) -> fmi2Status;
                fmi2GetBoolean: fmi2GetBooleanTYPE, (c: fmi2Component,
                    vr: *const fmi2ValueReference, nvr: usize,
                    value: *mut fmi2Boolean) -> fmi2Status;
                fmi2GetString: fmi2GetStringTYPE, (c: fmi2Component, vr: *const fmi2ValueReference,
                    nvr: usize, value: *mut fmi2String) -> fmi2Status;
                fmi2SetReal: fmi2SetRealTYPE, (c: fmi2Component, vr: *const fmi2ValueReference,
                    nvr: usize, value: *const fmi2Real) -> fmi2Status;
                fmi2SetInteger: fmi2SetIntegerTYPE, (c: fmi2Component,
                    vr: *const fmi2ValueReference, nvr: usize,
                    value: *const fmi2Integer) -> fmi2Status;
                fmi2SetBoolean: fmi2SetBooleanTYPE, (c: fmi2Component,
                    vr: *const fmi2ValueReference, nvr: usize,
                    value: *const fmi2Boolean) -> fmi2Status;
                fmi2SetString: fmi2SetStringTYPE, (c: fmi2Component, vr: *const fmi2ValueReference,
                    nvr: usize, value: *const fmi2String) -> fmi2Status;
                fmi2GetFMUstate: fmi2GetFMUstateTYPE, (c: fmi2Component,
                    FMUstate: *mut fmi2FMUstate) -> fmi2Status;
                fmi2SetFMUstate: fmi2SetFMUstateTYPE, (c: fmi2Component,
                    FMUstate: fmi2FMUstate) -> fmi2Status;
                fmi2FreeFMUstate: fmi2FreeFMUstateTYPE, (c: fmi2Component,
                    FMUstate: *mut fmi2FMUstate) -> fmi2Status;
                fmi2SerializedFMUstateSize: fmi2SerializedFMUstateSizeTYPE, (c: fmi2Component,
                    FMUstate: fmi2FMUstate, size: *mut usize) -> fmi2Status;
                fmi2SerializeFMUstate: fmi2SerializeFMUstateTYPE, (c: fmi2Component,
                    FMUstate: fmi2FMUstate, serializedState: *mut fmi2Byte,
                    size: usize) -> fmi2Status;
                fmi2DeSerializeFMUstate: fmi2DeSerializeFMUstateTYPE, (c: fmi2Component,
                    serializedState: *const fmi2Byte, size: usize,
                    FMUstate: *mut fmi2FMUstate) -> fmi2Status;
                fmi2GetDirectionalDerivative: fmi2GetDirectionalDerivativeTYPE, (c: fmi2Component,
                    _vUnknown_ref: *const fmi2ValueReference, _nUnknown: usize,
                    _vKnown_ref: *const fmi2ValueReference, _nKnown: usize,
                    _dvKnown: *const fmi2Real, _dvUnknown: *mut fmi2Real) -> fmi2Status;
                fmi2SetRealInputDerivatives: fmi2SetRealInputDerivativesTYPE, (c: fmi2Component,
                    vr: *const fmi2ValueReference, nvr: usize, order: *const fmi2Integer,
                    value: *const fmi2Real) -> fmi2Status;
                fmi2GetRealOutputDerivatives: fmi2GetRealOutputDerivativesTYPE, (c: fmi2Component,
                    vr: *const fmi2ValueReference, nvr: usize, order: *const fmi2Integer,
                    value: *mut fmi2Real) -> fmi2Status;
                fmi2DoStep: fmi2DoStepTYPE, (c: fmi2Component, currentCommunicationPoint: fmi2Real,
                    communicationStepSize: fmi2Real,
                    _noSetFMUStatePriorToCurrentPoint: fmi2Boolean) -> fmi2Status;
                fmi2CancelStep: fmi2CancelStepTYPE, (c: fmi2Component) -> fmi2Status;
                fmi2GetStatus: fmi2GetStatusTYPE, (c: fmi2Component, _s: fmi2StatusKind,
                    value: *mut fmi2Status) -> fmi2Status;
                fmi2GetRealStatus: fmi2GetRealStatusTYPE, (c: fmi2Component, s: fmi2StatusKind,
                    value: *mut fmi2Real) -> fmi2Status;
                fmi2GetIntegerStatus: fmi2GetIntegerStatusTYPE, (c: fmi2Component,
                    _s: fmi2StatusKind, value: *mut fmi2Integer) -> fmi2Status;
                fmi2GetBooleanStatus: fmi2GetBooleanStatusTYPE, (c: fmi2Component,
                    s: fmi2StatusKind, value: *mut fmi2Boolean) -> fmi2Status;
                fmi2GetStringStatus: fmi2GetStringStatusTYPE, (c: fmi2Component,
                    _s: fmi2StatusKind, value: *mut fmi2String) -> fmi2Status;
            );
        }
    };
}
