"""What the support does: ground-motion records, pulses, record and design spectra."""
