// A vessel segment for the getme pipeline example, with all four element types: a tetrahedral
// core, a ring of prisms (extruded triangles), an outer wall layer of hexahedra (extruded quads),
// and the pyramids gmsh inserts where the core's tetrahedra meet the prisms' quadrilateral faces.
// Physical groups name what a solver needs: inlet, outlet, wall, fluid.
SetFactory("OpenCASCADE");
radius = 1.0;
length = 3.0;
Disk(1) = {0, 0, 0, 0.7};
Disk(2) = {0, 0, 0, 0.85};
Disk(3) = {0, 0, 0, radius};
BooleanFragments{ Surface{3}; Delete; }{ Surface{1, 2}; Delete; }
Mesh.MeshSizeMax = 0.25;
eps = 1e-6;
core() = Surface In BoundingBox{-0.71, -0.71, -eps, 0.71, 0.71, eps};
inner() = Surface In BoundingBox{-0.86, -0.86, -eps, 0.86, 0.86, eps};
inner() -= core();
outer() = Surface{:};
outer() -= inner();
outer() -= core();
Recombine Surface{outer()};
prisms() = Extrude{0, 0, length}{ Surface{inner()}; Layers{12}; Recombine; };
hexes() = Extrude{0, 0, length}{ Surface{outer()}; Layers{12}; Recombine; };
tets() = Extrude{0, 0, length}{ Surface{core()}; };
Physical Surface("inlet", 1) = Surface In BoundingBox{-2, -2, -eps, 2, 2, eps};
Physical Surface("outlet", 2) = Surface In BoundingBox{-2, -2, length - eps, 2, 2, length + eps};
wall() = Surface In BoundingBox{-2, -2, -eps, 2, 2, length + eps};
inside() = Surface In BoundingBox{-0.86, -0.86, -eps, 0.86, 0.86, length + eps};
wall() -= inside();
wall() -= Surface In BoundingBox{-2, -2, -eps, 2, 2, eps};
wall() -= Surface In BoundingBox{-2, -2, length - eps, 2, 2, length + eps};
Physical Surface("wall", 3) = {wall()};
Physical Volume("fluid", 10) = Volume{:};
