//! The master's logger, with categories and the debug-logging switch.
//!
//! FMI 2 messages go through `"%s"` (never as the format string), with `#` doubled because `#r12#`
//! is the FMI 2 value-reference macro (FMI 2.0.4 §2.1.5); FMI 3's callback takes the message as it
//! is (FMI 3.0 §2.3.1). Error and fatal messages are always logged.

use std::ffi::CString;

use super::callback::{call_logger, call_logger3};

use fmi_sys::fmi2::{
    fmi2CallbackLogger, fmi2ComponentEnvironment, fmi2Status, fmi2Status_fmi2Discard,
    fmi2Status_fmi2Error, fmi2Status_fmi2OK, fmi2Status_fmi2Warning,
};
use fmi_sys::fmi3::{fmi3InstanceEnvironment, fmi3LogMessageCallback};

/// Where an instance's messages go: the callback of the FMI version it was instantiated by.
#[derive(Debug)]
enum Sink {
    /// fmi2CallbackLogger, with the instance's name as its second argument.
    Fmi2 {
        callback: fmi2CallbackLogger,
        environment: fmi2ComponentEnvironment,
        instance_name: CString,
    },
    /// fmi3LogMessageCallback.
    Fmi3 {
        callback: fmi3LogMessageCallback,
        environment: fmi3InstanceEnvironment,
    },
}

/// The logger callback of one instance.
#[derive(Debug)]
pub struct Logger {
    sink: Sink,
    debug: bool,
    /// The model's log categories (name, description).
    categories: &'static [(&'static str, &'static str)],
    enabled: Vec<bool>,
}

impl Logger {
    /// A logger calling `callback(environment, instance_name, …)`.
    pub fn new(
        callback: fmi2CallbackLogger,
        environment: fmi2ComponentEnvironment,
        instance_name: &str,
        debug: bool,
        categories: &'static [(&'static str, &'static str)],
    ) -> Self {
        Self {
            sink: Sink::Fmi2 {
                callback,
                environment,
                instance_name: CString::new(instance_name.replace('\0', "")).unwrap_or_default(),
            },
            debug,
            categories,
            enabled: vec![true; categories.len()],
        }
    }

    /// A logger calling FMI 3's `callback(environment, …)`.
    pub fn fmi3(
        callback: fmi3LogMessageCallback,
        environment: fmi3InstanceEnvironment,
        debug: bool,
        categories: &'static [(&'static str, &'static str)],
    ) -> Self {
        Self {
            sink: Sink::Fmi3 {
                callback,
                environment,
            },
            debug,
            categories,
            enabled: vec![true; categories.len()],
        }
    }

    fn category_index(&self, name: &str) -> Option<usize> {
        self.categories.iter().position(|(n, _)| *n == name)
    }

    /// fmi2SetDebugLogging: switch debug logging and, if `categories` is not empty, enable
    /// only those. An unknown category is an error naming it.
    pub fn set_debug_logging(&mut self, on: bool, categories: &[String]) -> Result<(), String> {
        let mut enabled = vec![categories.is_empty(); self.categories.len()];
        for c in categories {
            let i = self.category_index(c).ok_or_else(|| {
                let known: Vec<&str> = self.categories.iter().map(|(n, _)| *n).collect();
                format!("unknown log category \"{c}\"; known: {}", known.join(", "))
            })?;
            enabled[i] = true;
        }
        self.debug = on;
        self.enabled = enabled;
        Ok(())
    }

    /// Sends one message; the status codes of FMI 2 and FMI 3 are the same numbers.
    fn emit(&self, status: fmi2Status, category: &str, message: &str) {
        let category = CString::new(category).unwrap_or_default();
        match &self.sink {
            Sink::Fmi2 {
                callback,
                environment,
                instance_name,
            } => {
                let text =
                    CString::new(message.replace('#', "##").replace('\0', "")).unwrap_or_default();
                call_logger(
                    *callback,
                    *environment,
                    instance_name,
                    status,
                    &category,
                    &text,
                );
            }
            Sink::Fmi3 {
                callback,
                environment,
            } => {
                let text = CString::new(message.replace('\0', "")).unwrap_or_default();
                call_logger3(*callback, *environment, status, &category, &text);
            }
        }
    }

    /// Logs an error (always, whatever the debug switch).
    pub fn error(&self, message: &str) {
        self.emit(fmi2Status_fmi2Error, "logStatusError", message);
    }

    /// Logs a discarded step (always).
    pub fn discard(&self, message: &str) {
        self.emit(fmi2Status_fmi2Discard, "logStatusDiscard", message);
    }

    /// Logs a warning if debug logging is on.
    pub fn warning(&self, message: &str) {
        self.debug_message(fmi2Status_fmi2Warning, "logStatusWarning", message);
    }

    /// Logs an event message if debug logging and the category are on.
    pub fn event(&self, message: &str) {
        self.debug_message(fmi2Status_fmi2OK, "logEvents", message);
    }

    fn debug_message(&self, status: fmi2Status, category: &str, message: &str) {
        let on = self
            .category_index(category)
            .is_some_and(|i| self.enabled[i])
            || self
                .category_index("logAll")
                .is_some_and(|i| self.enabled[i]);
        if self.debug && on {
            self.emit(status, category, message);
        }
    }
}
