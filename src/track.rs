//! Track placement (placeholder, being written).
