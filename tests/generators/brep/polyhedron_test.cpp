// Filled in with the synthetic B-Rep generator.
