// Fuzz target: the ParaView camera file reader of lct-render (RenderKeys::ReadPvcc in
// Examples/RenderKeys.h) on arbitrary bytes. ReadPvcc takes a file name, so each input is written
// to a temporary file first. As lct-render does with `lct-render a.pvcc b.pvcc`, the camera read
// becomes the key at t = 0 and a second, fixed camera the key at t = 1 (the built-in flight's
// second key), and the keys are then used as lct-render uses them (FuzzRenderKeys.h). Seeds:
// Testing/Data/Render/*.pvcc; dictionary: FuzzRenderKeysPvcc.dict.
//
// Properties: no crash, sanitizer report or hang; ReadPvcc returns a camera or throws
// RenderKeys::InputError and nothing else; accepted keys render.
#include "FuzzInput.h"
#include "FuzzRenderKeys.h"

#include <exception>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  lct_fuzz::QuietOutputWindow::Install();
  lct_fuzz::SilenceStdErr();
  const std::string& file = lct_fuzz::InputAsFile("lct-fuzz-pvcc", data, size);
  RenderKeys::Keys keys;
  keys.Source = file;
  try
  {
    keys.Camera.push_back(RenderKeys::ReadPvcc(file, 0.0));
  }
  catch (const RenderKeys::InputError&)
  {
    return 0;
  }
  catch (const std::exception& e)
  {
    LCT_FUZZ_CHECK(false, "ReadPvcc threw something other than InputError: " << e.what());
  }
  RenderKeys::CameraKey second;
  second.Time = 1.0;
  second.Camera = vtkSmartPointer<vtkCamera>::New();
  CameraFlightScene::MakeKey(1, second.Camera);
  second.Path = "camera.keys[1]";
  keys.Camera.push_back(second);
  lct_fuzz::RenderKeysLikeLctRender(keys);
  return 0;
}
