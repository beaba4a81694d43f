// Tests of slice_loft: written with the method.
