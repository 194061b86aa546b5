//! MIT* and EIT*.

#![forbid(unsafe_code)]
