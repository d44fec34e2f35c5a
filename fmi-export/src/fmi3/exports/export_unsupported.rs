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
        /// Enters Event Mode (a model with hasEventMode, an instance with eventModeUsed).
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3EnterEventMode(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's argument, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3EnterEventMode::<$model>(instance) }
        }
        const _: $crate::fmi3::exports::sys::fmi3EnterEventModeTYPE = Some(fmi3EnterEventMode);
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
        /// Enters Configuration Mode (a model with structural parameters).
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3EnterConfigurationMode(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's argument, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3EnterConfigurationMode::<$model>(instance) }
        }
        const _: $crate::fmi3::exports::sys::fmi3EnterConfigurationModeTYPE =
            Some(fmi3EnterConfigurationMode);
        /// Leaves Configuration Mode.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3ExitConfigurationMode(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's argument, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3ExitConfigurationMode::<$model>(instance) }
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
        /// Not supported: providesEvaluateDiscreteStates = false (the model settles its discrete
        /// states where its events happen).
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3EvaluateDiscreteStates(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            $crate::fmi3::exports::unsupported::<$model>(
                instance,
                "fmi3EvaluateDiscreteStates",
                "the discrete states are not evaluated apart (providesEvaluateDiscreteStates = false)",
            )
        }
        const _: $crate::fmi3::exports::sys::fmi3EvaluateDiscreteStatesTYPE =
            Some(fmi3EvaluateDiscreteStates);
        /// Settles the discrete states in Event Mode.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3UpdateDiscreteStates(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
            discreteStatesNeedUpdate: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            terminateSimulation: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            nominalsOfContinuousStatesChanged: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            valuesOfContinuousStatesChanged: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            nextEventTimeDefined: *mut $crate::fmi3::exports::sys::fmi3Boolean,
            nextEventTime: *mut $crate::fmi3::exports::sys::fmi3Float64,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's arguments, passed on unchanged under the same contract.
            unsafe {
                $crate::fmi3::exports::fmi3UpdateDiscreteStates::<$model>(
                    instance,
                    discreteStatesNeedUpdate,
                    terminateSimulation,
                    nominalsOfContinuousStatesChanged,
                    valuesOfContinuousStatesChanged,
                    nextEventTimeDefined,
                    nextEventTime,
                )
            }
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
        /// Leaves Event Mode for Step Mode.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn fmi3EnterStepMode(
            instance: $crate::fmi3::exports::sys::fmi3Instance,
        ) -> $crate::fmi3::exports::sys::fmi3Status {
            // SAFETY: the master's argument, passed on unchanged under the same contract.
            unsafe { $crate::fmi3::exports::fmi3EnterStepMode::<$model>(instance) }
        }
        const _: $crate::fmi3::exports::sys::fmi3EnterStepModeTYPE = Some(fmi3EnterStepMode);
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
