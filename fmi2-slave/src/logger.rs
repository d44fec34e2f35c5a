//! The master's logger, with categories and the debug-logging switch.
//!
//! Messages go through `"%s"` (never as the format string), with `#` doubled because `#r12#` is the
//! FMI 2 value-reference macro (FMI 2.0.4 §2.1.5). Error and fatal messages are always logged.

use std::ffi::CString;

use super::callback::call_logger;

use fmi_sys::fmi2::{
    fmi2CallbackLogger, fmi2ComponentEnvironment, fmi2Status, fmi2Status_fmi2Discard,
    fmi2Status_fmi2Error, fmi2Status_fmi2OK, fmi2Status_fmi2Warning,
};

/// The logger callback of one instance.
#[derive(Debug)]
pub struct Logger {
    callback: fmi2CallbackLogger,
    environment: fmi2ComponentEnvironment,
    instance_name: CString,
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
            callback,
            environment,
            instance_name: CString::new(instance_name.replace('\0', "")).unwrap_or_default(),
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

    fn emit(&self, status: fmi2Status, category: &str, message: &str) {
        let text = CString::new(message.replace('#', "##").replace('\0', "")).unwrap_or_default();
        let category = CString::new(category).unwrap_or_default();
        call_logger(
            self.callback,
            self.environment,
            &self.instance_name,
            status,
            &category,
            &text,
        );
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
