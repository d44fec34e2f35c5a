//! The FMI 3 functions of modes and capabilities beyond stepping, under their C names, for
//! [`crate::export_fmi3!`]: Configuration Mode and Event Mode forward to the layer (which refuses
//! them for a model without structural parameters or event mode); those the FMU does not declare
//! (clocks, model exchange, scheduled execution, adjoint derivatives, variable dependencies)
//! return fmi3Error with the reason logged.

/// Part of [`crate::export_fmi3!`], which invokes it.
#[doc(hidden)]
#[macro_export]
macro_rules! export_fmi3_unsupported {
    ($model:ty) => {
        $crate::forward_export!(fmi3, $model;
            fmi3EnterEventMode: fmi3EnterEventModeTYPE, (instance: fmi3Instance) -> fmi3Status;
        );
        $crate::fmi3_unsupported!($model;
            fmi3GetNumberOfVariableDependencies: fmi3GetNumberOfVariableDependenciesTYPE,
                "the dependencies are those of modelDescription.xml's ModelStructure",
                _valueReference: fmi3ValueReference, _nDependencies: *mut usize;
            fmi3GetVariableDependencies: fmi3GetVariableDependenciesTYPE,
                "the dependencies are those of modelDescription.xml's ModelStructure",
                _dependent: fmi3ValueReference, _elementIndicesOfDependent: *mut usize,
                _independents: *mut fmi3ValueReference, _elementIndicesOfIndependents: *mut usize,
                _dependencyKinds: *mut fmi3DependencyKind, _nDependencies: usize;
            fmi3GetAdjointDerivative: fmi3GetAdjointDerivativeTYPE,
                "adjoint derivatives are not provided (providesAdjointDerivatives = false)",
                _unknowns: *const fmi3ValueReference, _nUnknowns: usize,
                _knowns: *const fmi3ValueReference, _nKnowns: usize, _seed: *const fmi3Float64,
                _nSeed: usize, _sensitivity: *mut fmi3Float64, _nSensitivity: usize;
        );
        $crate::forward_export!(fmi3, $model;
            fmi3EnterConfigurationMode: fmi3EnterConfigurationModeTYPE,
                (instance: fmi3Instance) -> fmi3Status;
            fmi3ExitConfigurationMode: fmi3ExitConfigurationModeTYPE,
                (instance: fmi3Instance) -> fmi3Status;
        );
        $crate::fmi3_unsupported!($model;
            fmi3GetIntervalDecimal: fmi3GetIntervalDecimalTYPE, "the FMU has no clocks",
                _valueReferences: *const fmi3ValueReference, _nValueReferences: usize,
                _intervals: *mut fmi3Float64, _qualifiers: *mut fmi3IntervalQualifier;
            fmi3GetIntervalFraction: fmi3GetIntervalFractionTYPE, "the FMU has no clocks",
                _valueReferences: *const fmi3ValueReference, _nValueReferences: usize,
                _counters: *mut fmi3UInt64, _resolutions: *mut fmi3UInt64,
                _qualifiers: *mut fmi3IntervalQualifier;
            fmi3GetShiftDecimal: fmi3GetShiftDecimalTYPE, "the FMU has no clocks",
                _valueReferences: *const fmi3ValueReference, _nValueReferences: usize,
                _shifts: *mut fmi3Float64;
            fmi3GetShiftFraction: fmi3GetShiftFractionTYPE, "the FMU has no clocks",
                _valueReferences: *const fmi3ValueReference, _nValueReferences: usize,
                _counters: *mut fmi3UInt64, _resolutions: *mut fmi3UInt64;
            fmi3SetIntervalDecimal: fmi3SetIntervalDecimalTYPE, "the FMU has no clocks",
                _valueReferences: *const fmi3ValueReference, _nValueReferences: usize,
                _intervals: *const fmi3Float64;
            fmi3SetIntervalFraction: fmi3SetIntervalFractionTYPE, "the FMU has no clocks",
                _valueReferences: *const fmi3ValueReference, _nValueReferences: usize,
                _counters: *const fmi3UInt64, _resolutions: *const fmi3UInt64;
            fmi3SetShiftDecimal: fmi3SetShiftDecimalTYPE, "the FMU has no clocks",
                _valueReferences: *const fmi3ValueReference, _nValueReferences: usize,
                _shifts: *const fmi3Float64;
            fmi3SetShiftFraction: fmi3SetShiftFractionTYPE, "the FMU has no clocks",
                _valueReferences: *const fmi3ValueReference, _nValueReferences: usize,
                _counters: *const fmi3UInt64, _resolutions: *const fmi3UInt64;
            fmi3EvaluateDiscreteStates: fmi3EvaluateDiscreteStatesTYPE,
                "the discrete states are not evaluated apart (providesEvaluateDiscreteStates = false)";
        );
        $crate::forward_export!(fmi3, $model;
            fmi3UpdateDiscreteStates: fmi3UpdateDiscreteStatesTYPE, (instance: fmi3Instance,
                discreteStatesNeedUpdate: *mut fmi3Boolean, terminateSimulation: *mut fmi3Boolean,
                nominalsOfContinuousStatesChanged: *mut fmi3Boolean,
                valuesOfContinuousStatesChanged: *mut fmi3Boolean,
                nextEventTimeDefined: *mut fmi3Boolean,
                nextEventTime: *mut fmi3Float64) -> fmi3Status;
        );
        $crate::fmi3_unsupported!($model;
            fmi3EnterContinuousTimeMode: fmi3EnterContinuousTimeModeTYPE,
                "model exchange is not provided";
            fmi3CompletedIntegratorStep: fmi3CompletedIntegratorStepTYPE,
                "model exchange is not provided", _noSetFMUStatePriorToCurrentPoint: fmi3Boolean,
                _enterEventMode: *mut fmi3Boolean, _terminateSimulation: *mut fmi3Boolean;
            fmi3SetTime: fmi3SetTimeTYPE, "model exchange is not provided", _time: fmi3Float64;
            fmi3SetContinuousStates: fmi3SetContinuousStatesTYPE, "model exchange is not provided",
                _continuousStates: *const fmi3Float64, _nContinuousStates: usize;
            fmi3GetContinuousStateDerivatives: fmi3GetContinuousStateDerivativesTYPE,
                "model exchange is not provided", _derivatives: *mut fmi3Float64,
                _nContinuousStates: usize;
            fmi3GetEventIndicators: fmi3GetEventIndicatorsTYPE, "model exchange is not provided",
                _eventIndicators: *mut fmi3Float64, _nEventIndicators: usize;
            fmi3GetContinuousStates: fmi3GetContinuousStatesTYPE, "model exchange is not provided",
                _continuousStates: *mut fmi3Float64, _nContinuousStates: usize;
            fmi3GetNominalsOfContinuousStates: fmi3GetNominalsOfContinuousStatesTYPE,
                "model exchange is not provided", _nominals: *mut fmi3Float64,
                _nContinuousStates: usize;
            fmi3GetNumberOfEventIndicators: fmi3GetNumberOfEventIndicatorsTYPE,
                "model exchange is not provided", _nEventIndicators: *mut usize;
            fmi3GetNumberOfContinuousStates: fmi3GetNumberOfContinuousStatesTYPE,
                "model exchange is not provided", _nContinuousStates: *mut usize;
        );
        $crate::forward_export!(fmi3, $model;
            fmi3EnterStepMode: fmi3EnterStepModeTYPE, (instance: fmi3Instance) -> fmi3Status;
        );
        $crate::fmi3_unsupported!($model;
            fmi3ActivateModelPartition: fmi3ActivateModelPartitionTYPE,
                "scheduled execution is not provided", _clockReference: fmi3ValueReference,
                _activationTime: fmi3Float64;
        );
    };
}

/// `fmi3*` functions of capabilities the FMU does not declare, for
/// [`crate::export_fmi3_unsupported!`]: each `$name` under its C name with the arguments after the
/// instance (`$arg: $ty`, of the header's types, unused), its signature pinned to the header's
/// `$pinned`; it logs "not supported: `$why`" and returns fmi3Error
/// ([`crate::fmi3::exports::unsupported`]).
#[doc(hidden)]
#[macro_export]
macro_rules! fmi3_unsupported {
    ($model:ty; $($name:ident: $pinned:ident, $why:literal $(, $arg:ident: $ty:ty)* $(,)?;)*) => {$(
        #[doc = concat!("Not supported: ", $why, ".")]
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(
            instance: fmi3Instance,
            $($arg: $ty,)*
        ) -> fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(instance, stringify!($name), $why)
        }
        const _: $pinned = Some($name);
    )*};
}
