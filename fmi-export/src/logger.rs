//! The master's logger, with categories and the debug-logging switch. Where a message goes is the
//! instantiating FMI version's business ([`LogSink`]: FMI 2's printf-style callback, FMI 3's);
//! error and discard messages are always logged, the others when debug logging and their category
//! are on.

use crate::status::Status;

/// The master's logger callback as the FMI version that created the instance calls it.
pub trait LogSink: std::fmt::Debug {
    /// Passes one message of `category` with `status` to the master.
    fn emit(&self, status: Status, category: &str, message: &str);
}

/// The logger of one instance.
#[derive(Debug)]
pub struct Logger {
    /// None: messages go nowhere (the reference driver).
    sink: Option<Box<dyn LogSink>>,
    debug: bool,
    /// The model's log categories (name, description).
    categories: &'static [(&'static str, &'static str)],
    enabled: Vec<bool>,
}

impl Logger {
    /// A logger sending to `sink`, debug logging `debug`, every category of `categories` on.
    pub fn new(
        sink: Box<dyn LogSink>,
        debug: bool,
        categories: &'static [(&'static str, &'static str)],
    ) -> Self {
        Self {
            sink: Some(sink),
            debug,
            categories,
            enabled: vec![true; categories.len()],
        }
    }

    /// A logger that drops every message.
    pub fn silent(categories: &'static [(&'static str, &'static str)]) -> Self {
        Self {
            sink: None,
            debug: false,
            categories,
            enabled: vec![true; categories.len()],
        }
    }

    fn category_index(&self, name: &str) -> Option<usize> {
        self.categories.iter().position(|(n, _)| *n == name)
    }

    /// SetDebugLogging: switch debug logging and, if `categories` is not empty, enable
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

    fn emit(&self, status: Status, category: &str, message: &str) {
        if let Some(sink) = &self.sink {
            sink.emit(status, category, message);
        }
    }

    /// Logs an error (always, whatever the debug switch).
    pub fn error(&self, message: &str) {
        self.emit(Status::Error, "logStatusError", message);
    }

    /// Logs a discarded step (always).
    pub fn discard(&self, message: &str) {
        self.emit(Status::Discard, "logStatusDiscard", message);
    }

    /// Logs a warning if debug logging is on.
    pub fn warning(&self, message: &str) {
        self.debug_message(Status::Warning, "logStatusWarning", message);
    }

    /// Logs an event message if debug logging and the category are on.
    pub fn event(&self, message: &str) {
        self.debug_message(Status::Ok, "logEvents", message);
    }

    fn debug_message(&self, status: Status, category: &str, message: &str) {
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
