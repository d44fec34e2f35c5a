//! A byte codec for serialized FMU states: little-endian numbers, length-prefixed vectors and
//! flags, read back with every truncation, over-long vector and invalid flag refused. Models
//! write their records with it (the slider-crank adds its own record types on top).

/// Largest accepted vector length in a serialized state.
const MAX_LENGTH: usize = 1 << 20;

/// Why bytes could not be read.
#[derive(Clone, Debug, PartialEq)]
pub struct CodecError(pub String);

/// Appends little-endian values to a byte vector.
pub struct ByteWriter<'a>(pub &'a mut Vec<u8>);

impl ByteWriter<'_> {
    /// Writes a byte.
    pub fn u8(&mut self, v: u8) {
        self.0.push(v);
    }
    /// Writes a u32.
    pub fn u32(&mut self, v: u32) {
        self.0.extend_from_slice(&v.to_le_bytes());
    }
    /// Writes a u64.
    pub fn u64(&mut self, v: u64) {
        self.0.extend_from_slice(&v.to_le_bytes());
    }
    /// Writes an f64 by its bits.
    pub fn f64(&mut self, v: f64) {
        self.u64(v.to_bits());
    }
    /// Writes a vector: its length (u32), then its values.
    pub fn f64s(&mut self, v: &[f64]) {
        self.u32(v.len() as u32);
        for x in v {
            self.f64(*x);
        }
    }
    /// Writes a flag as one byte, 0 or 1.
    pub fn flag(&mut self, v: bool) {
        self.u8(u8::from(v));
    }
    /// Writes a string: its length in bytes (u32), then its UTF-8 bytes.
    pub fn str(&mut self, v: &str) {
        self.u32(v.len() as u32);
        self.0.extend_from_slice(v.as_bytes());
    }
}

/// Reads what [`ByteWriter`] wrote, refusing truncated input, over-long vectors and invalid flags.
pub struct ByteReader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> ByteReader<'a> {
    /// A reader at the start of `bytes`.
    pub fn new(bytes: &'a [u8]) -> Self {
        Self { bytes, at: 0 }
    }

    /// Bytes not read yet.
    pub fn remaining(&self) -> usize {
        self.bytes.len() - self.at
    }

    /// The next `n` bytes.
    pub fn take(&mut self, n: usize) -> Result<&[u8], CodecError> {
        let end = self
            .at
            .checked_add(n)
            .filter(|&e| e <= self.bytes.len())
            .ok_or_else(|| {
                CodecError(format!("FMU state truncated: {} bytes", self.bytes.len()))
            })?;
        let out = &self.bytes[self.at..end];
        self.at = end;
        Ok(out)
    }
    /// Reads a byte.
    pub fn u8(&mut self) -> Result<u8, CodecError> {
        Ok(self.take(1)?[0])
    }
    /// Reads a u32.
    pub fn u32(&mut self) -> Result<u32, CodecError> {
        let mut b = [0; 4];
        b.copy_from_slice(self.take(4)?);
        Ok(u32::from_le_bytes(b))
    }
    /// Reads a u64.
    pub fn u64(&mut self) -> Result<u64, CodecError> {
        let mut b = [0; 8];
        b.copy_from_slice(self.take(8)?);
        Ok(u64::from_le_bytes(b))
    }
    /// Reads an f64.
    pub fn f64(&mut self) -> Result<f64, CodecError> {
        Ok(f64::from_bits(self.u64()?))
    }
    /// Reads a vector of at most 2^20 values.
    pub fn f64s(&mut self) -> Result<Vec<f64>, CodecError> {
        let n = self.u32()? as usize;
        if n > MAX_LENGTH {
            return Err(CodecError(format!(
                "FMU state rejected: a vector of {n} values"
            )));
        }
        (0..n).map(|_| self.f64()).collect()
    }
    /// Reads a string of at most 2^20 bytes of UTF-8.
    pub fn str(&mut self) -> Result<String, CodecError> {
        let n = self.u32()? as usize;
        if n > MAX_LENGTH {
            return Err(CodecError(format!(
                "FMU state rejected: a string of {n} bytes"
            )));
        }
        String::from_utf8(self.take(n)?.to_vec())
            .map_err(|_| CodecError("FMU state rejected: a string that is not UTF-8".into()))
    }
    /// Reads a flag: 0 or 1, any other byte is an error.
    pub fn flag(&mut self) -> Result<bool, CodecError> {
        match self.u8()? {
            0 => Ok(false),
            1 => Ok(true),
            b => Err(CodecError(format!("FMU state: invalid flag byte {b}"))),
        }
    }
}
