//! The RT-components, one per file, named as in the seeds (SPEC §0).
