height_field { function 1e9, 1e9 { x } }
