// The example sphere (sphere.geo) with a made-up "temperature" field, sin(3x) cos(3y) + z / 2,
// saved as $NodeData for examples/field.toml: NewView makes a zero view on the mesh and
// ModifyComponents fills it in place (it stays mesh-based, so Save View writes $NodeData).
// Made by scripts/make_field_fixtures.sh: gmsh field_sphere.geo -0.
Include "sphere.geo";
Mesh 2;
Plugin(NewView).NumComp = 1;
Plugin(NewView).Type = "NodeData";
Plugin(NewView).Run;
Plugin(ModifyComponents).Expression0 = "Sin(3*x)*Cos(3*y) + z/2";
Plugin(ModifyComponents).View = 0;
Plugin(ModifyComponents).Run;
View[0].Name = "temperature";
PostProcessing.SaveMesh = 1;
Mesh.MshFileVersion = 4.1;
Mesh.Binary = 1;
Save View[0] "field_sphere.msh";
