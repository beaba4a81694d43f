// Tests of crest_feature: written with the method.
