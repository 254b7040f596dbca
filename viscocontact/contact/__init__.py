"""Contact-mechanics internals: meshes, fixed-edge field solutions, edge terms, contact sets."""
