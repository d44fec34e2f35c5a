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
        /// See `fmi_export::fmi2::exports::fmi2Instantiate`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2Instantiate(
            instanceName: $crate::fmi2::exports::sys::fmi2String,
            fmuType: $crate::fmi2::exports::sys::fmi2Type,
            fmuGUID: $crate::fmi2::exports::sys::fmi2String,
            _fmuResourceLocation: $crate::fmi2::exports::sys::fmi2String,
            functions: *const $crate::fmi2::exports::sys::fmi2CallbackFunctions,
            _visible: $crate::fmi2::exports::sys::fmi2Boolean,
            loggingOn: $crate::fmi2::exports::sys::fmi2Boolean,
        ) -> $crate::fmi2::exports::sys::fmi2Component {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi2::exports::fmi2Instantiate::<$model>(
                    instanceName,
                    fmuType,
                    fmuGUID,
                    _fmuResourceLocation,
                    functions,
                    _visible,
                    loggingOn,
                )
            }
        }
        const _: $crate::fmi2::exports::sys::fmi2InstantiateTYPE = Some(fmi2Instantiate);
        /// See `fmi_export::fmi2::exports::fmi2FreeInstance`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2FreeInstance(c: $crate::fmi2::exports::sys::fmi2Component) {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2FreeInstance::<$model>(c) }
        }
        const _: $crate::fmi2::exports::sys::fmi2FreeInstanceTYPE = Some(fmi2FreeInstance);
        /// See `fmi_export::fmi2::exports::fmi2SetDebugLogging`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SetDebugLogging(
            c: $crate::fmi2::exports::sys::fmi2Component,
            loggingOn: $crate::fmi2::exports::sys::fmi2Boolean,
            nCategories: usize,
            categories: *const $crate::fmi2::exports::sys::fmi2String,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi2::exports::fmi2SetDebugLogging::<$model>(
                    c,
                    loggingOn,
                    nCategories,
                    categories,
                )
            }
        }
        const _: $crate::fmi2::exports::sys::fmi2SetDebugLoggingTYPE = Some(fmi2SetDebugLogging);
        /// See `fmi_export::fmi2::exports::fmi2SetupExperiment`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SetupExperiment(
            c: $crate::fmi2::exports::sys::fmi2Component,
            toleranceDefined: $crate::fmi2::exports::sys::fmi2Boolean,
            tolerance: $crate::fmi2::exports::sys::fmi2Real,
            startTime: $crate::fmi2::exports::sys::fmi2Real,
            stopTimeDefined: $crate::fmi2::exports::sys::fmi2Boolean,
            stopTime: $crate::fmi2::exports::sys::fmi2Real,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi2::exports::fmi2SetupExperiment::<$model>(
                    c,
                    toleranceDefined,
                    tolerance,
                    startTime,
                    stopTimeDefined,
                    stopTime,
                )
            }
        }
        const _: $crate::fmi2::exports::sys::fmi2SetupExperimentTYPE = Some(fmi2SetupExperiment);
        /// See `fmi_export::fmi2::exports::fmi2EnterInitializationMode`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2EnterInitializationMode(
            c: $crate::fmi2::exports::sys::fmi2Component,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2EnterInitializationMode::<$model>(c) }
        }
        const _: $crate::fmi2::exports::sys::fmi2EnterInitializationModeTYPE =
            Some(fmi2EnterInitializationMode);
        /// See `fmi_export::fmi2::exports::fmi2ExitInitializationMode`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2ExitInitializationMode(
            c: $crate::fmi2::exports::sys::fmi2Component,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2ExitInitializationMode::<$model>(c) }
        }
        const _: $crate::fmi2::exports::sys::fmi2ExitInitializationModeTYPE =
            Some(fmi2ExitInitializationMode);
        /// See `fmi_export::fmi2::exports::fmi2Terminate`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2Terminate(
            c: $crate::fmi2::exports::sys::fmi2Component,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2Terminate::<$model>(c) }
        }
        const _: $crate::fmi2::exports::sys::fmi2TerminateTYPE = Some(fmi2Terminate);
        /// See `fmi_export::fmi2::exports::fmi2Reset`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2Reset(
            c: $crate::fmi2::exports::sys::fmi2Component,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2Reset::<$model>(c) }
        }
        const _: $crate::fmi2::exports::sys::fmi2ResetTYPE = Some(fmi2Reset);
        /// See `fmi_export::fmi2::exports::fmi2GetReal`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetReal(
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *mut $crate::fmi2::exports::sys::fmi2Real,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2GetReal::<$model>(c, vr, nvr, value) }
        }
        const _: $crate::fmi2::exports::sys::fmi2GetRealTYPE = Some(fmi2GetReal);
        /// See `fmi_export::fmi2::exports::fmi2GetInteger`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetInteger(
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *mut $crate::fmi2::exports::sys::fmi2Integer,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2GetInteger::<$model>(c, vr, nvr, value) }
        }
        const _: $crate::fmi2::exports::sys::fmi2GetIntegerTYPE = Some(fmi2GetInteger);
        /// See `fmi_export::fmi2::exports::fmi2GetBoolean`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetBoolean(
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *mut $crate::fmi2::exports::sys::fmi2Boolean,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2GetBoolean::<$model>(c, vr, nvr, value) }
        }
        const _: $crate::fmi2::exports::sys::fmi2GetBooleanTYPE = Some(fmi2GetBoolean);
        /// See `fmi_export::fmi2::exports::fmi2GetString`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetString(
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *mut $crate::fmi2::exports::sys::fmi2String,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2GetString::<$model>(c, vr, nvr, value) }
        }
        const _: $crate::fmi2::exports::sys::fmi2GetStringTYPE = Some(fmi2GetString);
        /// See `fmi_export::fmi2::exports::fmi2SetReal`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SetReal(
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *const $crate::fmi2::exports::sys::fmi2Real,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2SetReal::<$model>(c, vr, nvr, value) }
        }
        const _: $crate::fmi2::exports::sys::fmi2SetRealTYPE = Some(fmi2SetReal);
        /// See `fmi_export::fmi2::exports::fmi2SetInteger`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SetInteger(
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *const $crate::fmi2::exports::sys::fmi2Integer,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2SetInteger::<$model>(c, vr, nvr, value) }
        }
        const _: $crate::fmi2::exports::sys::fmi2SetIntegerTYPE = Some(fmi2SetInteger);
        /// See `fmi_export::fmi2::exports::fmi2SetBoolean`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SetBoolean(
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *const $crate::fmi2::exports::sys::fmi2Boolean,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2SetBoolean::<$model>(c, vr, nvr, value) }
        }
        const _: $crate::fmi2::exports::sys::fmi2SetBooleanTYPE = Some(fmi2SetBoolean);
        /// See `fmi_export::fmi2::exports::fmi2SetString`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SetString(
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            value: *const $crate::fmi2::exports::sys::fmi2String,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2SetString::<$model>(c, vr, nvr, value) }
        }
        const _: $crate::fmi2::exports::sys::fmi2SetStringTYPE = Some(fmi2SetString);
        /// See `fmi_export::fmi2::exports::fmi2GetFMUstate`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetFMUstate(
            c: $crate::fmi2::exports::sys::fmi2Component,
            FMUstate: *mut $crate::fmi2::exports::sys::fmi2FMUstate,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2GetFMUstate::<$model>(c, FMUstate) }
        }
        const _: $crate::fmi2::exports::sys::fmi2GetFMUstateTYPE = Some(fmi2GetFMUstate);
        /// See `fmi_export::fmi2::exports::fmi2SetFMUstate`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SetFMUstate(
            c: $crate::fmi2::exports::sys::fmi2Component,
            FMUstate: $crate::fmi2::exports::sys::fmi2FMUstate,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2SetFMUstate::<$model>(c, FMUstate) }
        }
        const _: $crate::fmi2::exports::sys::fmi2SetFMUstateTYPE = Some(fmi2SetFMUstate);
        /// See `fmi_export::fmi2::exports::fmi2FreeFMUstate`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2FreeFMUstate(
            c: $crate::fmi2::exports::sys::fmi2Component,
            FMUstate: *mut $crate::fmi2::exports::sys::fmi2FMUstate,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2FreeFMUstate::<$model>(c, FMUstate) }
        }
        const _: $crate::fmi2::exports::sys::fmi2FreeFMUstateTYPE = Some(fmi2FreeFMUstate);
        /// See `fmi_export::fmi2::exports::fmi2SerializedFMUstateSize`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SerializedFMUstateSize(
            c: $crate::fmi2::exports::sys::fmi2Component,
            FMUstate: $crate::fmi2::exports::sys::fmi2FMUstate,
            size: *mut usize,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi2::exports::fmi2SerializedFMUstateSize::<$model>(c, FMUstate, size)
            }
        }
        const _: $crate::fmi2::exports::sys::fmi2SerializedFMUstateSizeTYPE =
            Some(fmi2SerializedFMUstateSize);
        /// See `fmi_export::fmi2::exports::fmi2SerializeFMUstate`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SerializeFMUstate(
            c: $crate::fmi2::exports::sys::fmi2Component,
            FMUstate: $crate::fmi2::exports::sys::fmi2FMUstate,
            serializedState: *mut $crate::fmi2::exports::sys::fmi2Byte,
            size: usize,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi2::exports::fmi2SerializeFMUstate::<$model>(
                    c,
                    FMUstate,
                    serializedState,
                    size,
                )
            }
        }
        const _: $crate::fmi2::exports::sys::fmi2SerializeFMUstateTYPE =
            Some(fmi2SerializeFMUstate);
        /// See `fmi_export::fmi2::exports::fmi2DeSerializeFMUstate`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
            c: $crate::fmi2::exports::sys::fmi2Component,
            serializedState: *const $crate::fmi2::exports::sys::fmi2Byte,
            size: usize,
            FMUstate: *mut $crate::fmi2::exports::sys::fmi2FMUstate,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi2::exports::fmi2DeSerializeFMUstate::<$model>(
                    c,
                    serializedState,
                    size,
                    FMUstate,
                )
            }
        }
        const _: $crate::fmi2::exports::sys::fmi2DeSerializeFMUstateTYPE =
            Some(fmi2DeSerializeFMUstate);
        /// See `fmi_export::fmi2::exports::fmi2GetDirectionalDerivative`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetDirectionalDerivative(
            c: $crate::fmi2::exports::sys::fmi2Component,
            _vUnknown_ref: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            _nUnknown: usize,
            _vKnown_ref: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            _nKnown: usize,
            _dvKnown: *const $crate::fmi2::exports::sys::fmi2Real,
            _dvUnknown: *mut $crate::fmi2::exports::sys::fmi2Real,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi2::exports::fmi2GetDirectionalDerivative::<$model>(
                    c,
                    _vUnknown_ref,
                    _nUnknown,
                    _vKnown_ref,
                    _nKnown,
                    _dvKnown,
                    _dvUnknown,
                )
            }
        }
        const _: $crate::fmi2::exports::sys::fmi2GetDirectionalDerivativeTYPE =
            Some(fmi2GetDirectionalDerivative);
        /// See `fmi_export::fmi2::exports::fmi2SetRealInputDerivatives`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2SetRealInputDerivatives(
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            order: *const $crate::fmi2::exports::sys::fmi2Integer,
            value: *const $crate::fmi2::exports::sys::fmi2Real,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi2::exports::fmi2SetRealInputDerivatives::<$model>(
                    c, vr, nvr, order, value,
                )
            }
        }
        const _: $crate::fmi2::exports::sys::fmi2SetRealInputDerivativesTYPE =
            Some(fmi2SetRealInputDerivatives);
        /// See `fmi_export::fmi2::exports::fmi2GetRealOutputDerivatives`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetRealOutputDerivatives(
            c: $crate::fmi2::exports::sys::fmi2Component,
            vr: *const $crate::fmi2::exports::sys::fmi2ValueReference,
            nvr: usize,
            order: *const $crate::fmi2::exports::sys::fmi2Integer,
            value: *mut $crate::fmi2::exports::sys::fmi2Real,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi2::exports::fmi2GetRealOutputDerivatives::<$model>(
                    c, vr, nvr, order, value,
                )
            }
        }
        const _: $crate::fmi2::exports::sys::fmi2GetRealOutputDerivativesTYPE =
            Some(fmi2GetRealOutputDerivatives);
        /// See `fmi_export::fmi2::exports::fmi2DoStep`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2DoStep(
            c: $crate::fmi2::exports::sys::fmi2Component,
            currentCommunicationPoint: $crate::fmi2::exports::sys::fmi2Real,
            communicationStepSize: $crate::fmi2::exports::sys::fmi2Real,
            _noSetFMUStatePriorToCurrentPoint: $crate::fmi2::exports::sys::fmi2Boolean,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi2::exports::fmi2DoStep::<$model>(
                    c,
                    currentCommunicationPoint,
                    communicationStepSize,
                    _noSetFMUStatePriorToCurrentPoint,
                )
            }
        }
        const _: $crate::fmi2::exports::sys::fmi2DoStepTYPE = Some(fmi2DoStep);
        /// See `fmi_export::fmi2::exports::fmi2CancelStep`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2CancelStep(
            c: $crate::fmi2::exports::sys::fmi2Component,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2CancelStep::<$model>(c) }
        }
        const _: $crate::fmi2::exports::sys::fmi2CancelStepTYPE = Some(fmi2CancelStep);
        /// See `fmi_export::fmi2::exports::fmi2GetStatus`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetStatus(
            c: $crate::fmi2::exports::sys::fmi2Component,
            _s: $crate::fmi2::exports::sys::fmi2StatusKind,
            value: *mut $crate::fmi2::exports::sys::fmi2Status,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2GetStatus::<$model>(c, _s, value) }
        }
        const _: $crate::fmi2::exports::sys::fmi2GetStatusTYPE = Some(fmi2GetStatus);
        /// See `fmi_export::fmi2::exports::fmi2GetRealStatus`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetRealStatus(
            c: $crate::fmi2::exports::sys::fmi2Component,
            s: $crate::fmi2::exports::sys::fmi2StatusKind,
            value: *mut $crate::fmi2::exports::sys::fmi2Real,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2GetRealStatus::<$model>(c, s, value) }
        }
        const _: $crate::fmi2::exports::sys::fmi2GetRealStatusTYPE = Some(fmi2GetRealStatus);
        /// See `fmi_export::fmi2::exports::fmi2GetIntegerStatus`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetIntegerStatus(
            c: $crate::fmi2::exports::sys::fmi2Component,
            _s: $crate::fmi2::exports::sys::fmi2StatusKind,
            value: *mut $crate::fmi2::exports::sys::fmi2Integer,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2GetIntegerStatus::<$model>(c, _s, value) }
        }
        const _: $crate::fmi2::exports::sys::fmi2GetIntegerStatusTYPE = Some(fmi2GetIntegerStatus);
        /// See `fmi_export::fmi2::exports::fmi2GetBooleanStatus`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetBooleanStatus(
            c: $crate::fmi2::exports::sys::fmi2Component,
            s: $crate::fmi2::exports::sys::fmi2StatusKind,
            value: *mut $crate::fmi2::exports::sys::fmi2Boolean,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2GetBooleanStatus::<$model>(c, s, value) }
        }
        const _: $crate::fmi2::exports::sys::fmi2GetBooleanStatusTYPE = Some(fmi2GetBooleanStatus);
        /// See `fmi_export::fmi2::exports::fmi2GetStringStatus`.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi2GetStringStatus(
            c: $crate::fmi2::exports::sys::fmi2Component,
            _s: $crate::fmi2::exports::sys::fmi2StatusKind,
            value: *mut $crate::fmi2::exports::sys::fmi2String,
        ) -> $crate::fmi2::exports::sys::fmi2Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe { $crate::fmi2::exports::fmi2GetStringStatus::<$model>(c, _s, value) }
        }
        const _: $crate::fmi2::exports::sys::fmi2GetStringStatusTYPE = Some(fmi2GetStringStatus);
    };
}
