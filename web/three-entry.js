// The part of three.js the gallery's 3D viewer uses (src/propulsor/export/web/viewer.js reads it as
// window.PROPULSOR_THREE); `make viewer-lib` bundles it into src/propulsor/export/web/three.min.js.
export {
  WebGLRenderer, Scene, PerspectiveCamera, OrthographicCamera, Group, Mesh, Box3, Vector2, Vector3, Plane,
  Color, AmbientLight, HemisphereLight, DirectionalLight, MeshStandardMaterial, DoubleSide, Raycaster,
  SRGBColorSpace, NoToneMapping, MathUtils, Matrix4, Quaternion, REVISION, AnimationMixer,
} from "three";
export { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
export { GLTFLoader } from "three/examples/jsm/loaders/GLTFLoader.js";
