"""The paper's tabletop study (Table II): tasks, rephrasings, baselines, the job and the report."""
