//! Reports: CSV tables, charts, HTML (placeholder, being written).
