// The unit square (square.geo) with one post-processing view whose value is x + 2 y, linear so that
// tests can check where each value lands: gmsh's NewView makes a zero view on the mesh, and
// ModifyComponents fills it in place, keeping it mesh-based so that Save View writes $NodeData or
// $ElementData (for elements gmsh evaluates x and y at the element's barycentre).
// With -setnumber volume 1, the second-order tetrahedra of cube_tet.geo instead; with -setnumber
// vector 1, the 3-component field (x, 2 y, 2) instead.
// Usage: gmsh field_square.geo -0 -setnumber elementData 0|1 -setstring out FILE.msh
//        -setnumber Mesh.MshFileVersion 2.2|4.1 -setnumber Mesh.Binary 0|1
DefineConstant[ elementData = 0, volume = 0, vector = 0, out = "field_square.msh" ];
If (volume)
  // Instead of the square: the volume-only cube of cube_tet.geo, second order.
  Include "cube_tet.geo";
  Mesh 3;
  SetOrder 2;
Else
  Include "square.geo";
  Mesh 2;
EndIf
If (vector)
  Plugin(NewView).NumComp = 3;
Else
  Plugin(NewView).NumComp = 1;
EndIf
If (elementData)
  Plugin(NewView).Type = "ElementData";
Else
  Plugin(NewView).Type = "NodeData";
EndIf
Plugin(NewView).Run;
If (vector)
  // A vector field (x, 2 y, 2): its magnitude is sqrt(x^2 + 4 y^2 + 4).
  Plugin(ModifyComponents).Expression0 = "x";
  Plugin(ModifyComponents).Expression1 = "2*y";
  Plugin(ModifyComponents).Expression2 = "2";
Else
  Plugin(ModifyComponents).Expression0 = "x + 2*y";
EndIf
Plugin(ModifyComponents).View = 0;
Plugin(ModifyComponents).Run;
View[0].Name = "temperature";
PostProcessing.SaveMesh = 1;
Save View[0] out;
