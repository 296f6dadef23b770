# PLACEHOLDER (scaffolding)
"""The wrapped module imports from /usr/bin/python3 and its class is a real VTK transform."""
import sys

from vtklct import vtkLogTransform
import vtkmodules.vtkCommonTransforms as vtkCommonTransforms

t = vtkLogTransform()
assert t.GetClassName() == "vtkLogTransform", t.GetClassName()
assert isinstance(t, vtkCommonTransforms.vtkLinearTransform), type(t).__mro__
assert t.IsA("vtkAbstractTransform")
m = t.GetMatrix()
assert all(abs(m.GetElement(i, j)) < 1e300 for i in range(4) for j in range(4))
print("vtklct OK from", sys.executable)
