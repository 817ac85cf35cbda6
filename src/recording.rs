//! Animated GIFs of the app: frames of RGBA pixels in, a GIF out, each frame
//! with its own palette (`NeuQuant`, deterministic), looping forever. The
//! command line's `record` and the app's record button share it.

/// A GIF being made.
pub struct GifRecording {
    encoder: gif::Encoder<Vec<u8>>,
    width: u16,
    height: u16,
    delay_cs: u16,
}

/// Why a recording failed.
#[derive(Debug, thiserror::Error)]
pub enum RecordingError {
    #[error("a frame of {got} bytes, expected {width}x{height} RGBA")]
    FrameSize { got: usize, width: u16, height: u16 },
    #[error(transparent)]
    Encoding(#[from] gif::EncodingError),
}

impl GifRecording {
    /// A GIF of `width` x `height` pixels at `fps` frames per second.
    ///
    /// # Errors
    /// The encoder's.
    pub fn new(width: u16, height: u16, fps: u16) -> Result<Self, RecordingError> {
        let mut encoder = gif::Encoder::new(Vec::new(), width, height, &[])?;
        encoder.set_repeat(gif::Repeat::Infinite)?;
        Ok(Self {
            encoder,
            width,
            height,
            // A frame's delay in hundredths of a second (GIF's unit).
            delay_cs: (100 / fps.max(1)).max(1),
        })
    }

    /// Adds a frame of RGBA pixels (the buffer is used for the quantizing).
    ///
    /// # Errors
    /// A frame of another size, or the encoder's.
    pub fn push(&mut self, rgba: &mut [u8]) -> Result<(), RecordingError> {
        self.push_lasting(rgba, self.delay_cs)
    }

    /// Adds a frame of RGBA pixels shown for `delay_cs` hundredths of a
    /// second (frames taken at an uneven rate, as a window's are).
    ///
    /// # Errors
    /// A frame of another size, or the encoder's.
    pub fn push_lasting(&mut self, rgba: &mut [u8], delay_cs: u16) -> Result<(), RecordingError> {
        let expected = usize::from(self.width) * usize::from(self.height) * 4;
        if rgba.len() != expected {
            return Err(RecordingError::FrameSize {
                got: rgba.len(),
                width: self.width,
                height: self.height,
            });
        }
        let mut frame = gif::Frame::from_rgba_speed(self.width, self.height, rgba, 10);
        frame.delay = delay_cs;
        self.encoder.write_frame(&frame)?;
        Ok(())
    }

    /// The GIF's bytes.
    ///
    /// # Errors
    /// The encoder's.
    pub fn finish(self) -> Result<Vec<u8>, RecordingError> {
        Ok(self.encoder.into_inner()?)
    }
}
